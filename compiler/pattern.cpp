#include "pattern.hpp"

namespace knitc {

int produced(const Course& course) {
  int n = 0;
  for (const Op& op : course.ops) n += stitch(op.stitch).produces;
  return n;
}

int consumed(const Course& course) {
  int n = 0;
  for (const Op& op : course.ops) n += stitch(op.stitch).consumes;
  return n;
}

long long loops_of(const Pattern& pattern) {
  long long loops = pattern.cast_on;
  for (const Course& c : pattern.courses) loops += produced(c);
  return loops;
}

}  // namespace knitc
