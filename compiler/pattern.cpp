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

}  // namespace knitc
