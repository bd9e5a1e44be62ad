#!/usr/bin/env bash
# Compares a pattern's snapshot with the one kept in tests/snapshots/NAME.snap.
# Usage: snapshot_check.sh KNITC PATTERN.lua SNAPFILE
# On a difference it prints the diff and writes the new result beside the old one as
# NAME.snap.new; ./scripts/accept-snapshots takes the new results.
set -u
knitc=$1 pattern=$2 snap=$3
new="$snap.new"
# A pattern knitc cannot compile yet keeps its error as its snapshot: when it starts to
# compile, the snapshot shows the change.
if ! "$knitc" snapshot "$pattern" --quiet >"$new" 2>"$new.err"; then
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
