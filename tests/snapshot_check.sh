#!/usr/bin/env bash
# Compares a pattern's snapshot with the one kept in tests/snapshots/NAME.snap.
# Usage: snapshot_check.sh KNITC PATTERN.lua SNAPFILE
# On a difference it prints the diff and writes the new result beside the old one as
# NAME.snap.new; ./scripts/accept-snapshots takes the new results.
set -u
knitc=$1 pattern=$2 snap=$3
new="$snap.new"
# A pattern that does not build fails, unless tests/snapshots/expected_failures lists it
# (one name a line): then its error is its snapshot, and it shows when that changes.
expected_failures="$(dirname "$snap")/expected_failures"
name=$(basename "$pattern" .lua)
if ! "$knitc" snapshot "$pattern" --quiet >"$new" 2>"$new.err"; then
  if ! grep -qx "$name" "$expected_failures" 2>/dev/null; then
    echo "$pattern does not build (and is not listed in $expected_failures):"
    cat "$new.err"
    rm -f "$new" "$new.err"
    exit 1
  fi
  { echo "error"; cat "$new.err"; } >"$new"
fi
rm -f "$new.err"
if [ -f "$snap" ] && cmp -s "$snap" "$new"; then
  rm -f "$new"
  exit 0
fi
if [ ! -f "$snap" ]; then
  echo "no snapshot for $pattern yet; the result is in $new (accept it with ./scripts/accept-snapshots)"
else
  diff -u "$snap" "$new"
  echo "the snapshot of $pattern changed; the new result is in $new (accept it with ./scripts/accept-snapshots)"
fi
exit 1
