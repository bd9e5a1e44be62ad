// Global curve interpolation through data points (P&T A9.1, and section 9.2.2 for end
// derivatives). Row k of the system matrix has non-zeros only in the p + 1 columns of its
// knot span, so an LU without pivoting, kept in those columns, solves it in O(n p^2).
// Piegl & Tiller show the matrix is totally positive, which makes the unpivoted
// elimination stable.
#include "nurbs.hpp"

#include "parallel.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace knitc::nurbs {

namespace {

// A square matrix whose row r has its non-zeros in the columns [first(r), first(r) + p]
// (p + 1 of them, its knot span's), first(r) ascending with r and r among them: so is the
// interpolation system. An LU without pivoting then fills nothing outside those columns
// (a pivot row k above r that reaches r, first(r) <= k, ends at first(k) + p <=
// first(r) + p), so each row is stored as its p + 1 cells and its first column: 4 doubles
// and an int a row for a cubic, where a band of 3 diagonals either side took 7 doubles (a
// garment's million-point curve's matrix was most of this stage's memory).
class ProfileMatrix {
 public:
  // The cells are left unset: each row is started (start_row) by whoever fills it, so a
  // garment's rows are first written in parallel, not zeroed by one thread first.
  ProfileMatrix(int size, int degree)
      : n_(size), width_(degree + 1), first_(new int[static_cast<std::size_t>(size)]),
        cells_(new double[static_cast<std::size_t>(size) * static_cast<std::size_t>(width_)]) {}

  // Row r's cells cleared, its first column `first` (r must lie in its columns).
  void start_row(int r, int first) {
    if (first > r || r - first >= width_) throw std::logic_error("nurbs: a row's diagonal outside its columns");
    first_[r] = first;
    std::fill(row_of(r) + first, row_of(r) + first + width_, 0.0);
  }

  double& at(int r, int c) {
    if (c < first_[r] || c >= first_[r] + width_) throw std::logic_error("nurbs: entry outside the row's columns");
    return row_of(r)[c];
  }

  // In-place LU without pivoting, then solves for every right-hand side column. (The
  // entries read inside the rows without at()'s check: a garment's curve is a million
  // rows.)
  void solve(std::vector<Point>& rhs) {
    for (int r = 1; r < n_; ++r)
      if (first_[r] < first_[r - 1]) throw std::logic_error("nurbs: the rows' first columns do not ascend");
    for (int k = 0; k < n_; ++k) {
      const double pivot = row_of(k)[k];
      if (std::abs(pivot) < 1e-300) throw std::invalid_argument("nurbs: singular interpolation system");
      const int last_c = std::min(n_ - 1, first_[k] + width_ - 1);
      for (int r = k + 1; r < n_ && first_[r] <= k; ++r) {
        double* row = row_of(r);
        const double f = row[k] / pivot;
        if (f == 0.0) continue;
        row[k] = f;
        const double* top = row_of(k);
        for (int c = k + 1; c <= last_c; ++c) row[c] -= f * top[c];
        rhs[static_cast<std::size_t>(r)] -= f * rhs[static_cast<std::size_t>(k)];
      }
    }
    for (int k = n_ - 1; k >= 0; --k) {
      Point v = rhs[static_cast<std::size_t>(k)];
      const double* row = row_of(k);
      for (int c = k + 1; c <= std::min(n_ - 1, first_[k] + width_ - 1); ++c) v -= row[c] * rhs[static_cast<std::size_t>(c)];
      rhs[static_cast<std::size_t>(k)] = v / row[k];
    }
  }

 private:
  // Row r's cells, shifted so that a column indexes them: row_of(r)[c] is (r, c) for c in
  // its columns.
  double* row_of(int r) {
    return cells_.get() + static_cast<std::ptrdiff_t>(r) * width_ - static_cast<std::ptrdiff_t>(first_[r]);
  }
  int n_, width_;
  std::unique_ptr<int[]> first_;
  std::unique_ptr<double[]> cells_;
};

std::vector<double> data_parameters(std::span<const Point> q, Parametrisation kind) {
  const std::size_t n = q.size() - 1;
  // Each step is found twice, not kept: a garment's are 14 MB.
  auto step = [&](std::size_t k) {
    const double chord = glm::distance(q[k], q[k - 1]);
    return kind == Parametrisation::centripetal ? std::sqrt(chord) : chord;
  };
  double total = 0.0;
  for (std::size_t k = 1; k <= n; ++k) {
    const double s = step(k);
    if (!(s > 0.0)) throw std::invalid_argument("nurbs: two consecutive data points coincide");
    total += s;
  }
  std::vector<double> u(n + 1);
  u[0] = 0.0;
  for (std::size_t k = 1; k < n; ++k) u[k] = u[k - 1] + step(k) / total;
  u[n] = 1.0;
  return u;
}

// Fills row `row` of the matrix with the basis functions at u. span: the knot span found
// for the last row (the rows' parameters ascend), walked on to u's.
void put_basis_row(ProfileMatrix& m, const Curve& c, int last, int row, double u, int& span) {
  while (span < last && c.knots[static_cast<std::size_t>(span) + 1] <= u) ++span;
  // find_span's span (the curve's control points are not made yet: it cannot be asked).
  assert(c.knots[static_cast<std::size_t>(span)] <= u && (span == last || u < c.knots[static_cast<std::size_t>(span) + 1]));
  BasisTable N;
  basis_derivatives(c, span, u, 0, N);
  m.start_row(row, span - c.degree);
  for (int j = 0; j <= c.degree; ++j) m.at(row, span - c.degree + j) = N[0][j];
}

}  // namespace

Interpolant interpolate(std::span<const Point> q, const InterpolationOptions& options) {
  if (q.size() < 2) throw std::invalid_argument("nurbs: interpolation needs at least two data points");
  const int n = static_cast<int>(q.size()) - 1;
  const bool with_ends = options.start_derivative.has_value() || options.end_derivative.has_value();
  if (with_ends && !(options.start_derivative && options.end_derivative))
    throw std::invalid_argument("nurbs: give both end derivatives or neither");

  Interpolant result;
  result.parameters = data_parameters(q, options.parametrisation);
  const auto& ub = result.parameters;
  Curve& c = result.curve;

  // Degree: cubic, lowered for too few points; end derivatives add two control points.
  const int controls = with_ends ? n + 3 : n + 1;
  const int p = std::min(3, controls - 1);
  c.degree = p;
  c.knots.assign(static_cast<std::size_t>(controls + p + 1), 0.0);
  for (int i = 0; i <= p; ++i) c.knots[c.knots.size() - 1 - i] = 1.0;
  if (!with_ends) {
    for (int j = 1; j <= n - p; ++j) {  // eq. 9.8
      double s = 0.0;
      for (int i = j; i <= j + p - 1; ++i) s += ub[i];
      c.knots[j + p] = s / p;
    }
  } else {
    for (int j = 0; j <= n - p + 1; ++j) {  // eq. 9.22
      double s = 0.0;
      for (int i = j; i <= j + p - 1; ++i) s += ub[std::min(i, n)];
      c.knots[j + p + 1] = s / p;
    }
  }
  const int last = controls - 1;  // the last control point's index

  // Each block of rows starts its walk where one walk over every row found its first span.
  constexpr int block = 16384;
  const int first_row = with_ends ? 1 : 0, last_row = with_ends ? n - 1 : n;  // data rows' k
  const int rows = std::max(0, last_row - first_row + 1);
  const int blocks = (rows + block - 1) / block;
  std::vector<int> block_span(static_cast<std::size_t>(blocks), p);
  {
    int walk = p;
    for (int k = first_row; k <= last_row; k += block) {
      while (walk < last && c.knots[static_cast<std::size_t>(walk) + 1] <= ub[k]) ++walk;
      block_span[static_cast<std::size_t>((k - first_row) / block)] = walk;
    }
  }
  ProfileMatrix m(controls, p);
  std::vector<Point> rhs = with_ends ? std::vector<Point>(static_cast<std::size_t>(controls)) : std::vector<Point>(q.begin(), q.end());
  parallel_for(static_cast<std::size_t>(blocks), thread_count(options.threads), [&](std::size_t b) {
    int span = block_span[b];
    const int from = first_row + static_cast<int>(b) * block, to = std::min(last_row, from + block - 1);
    for (int k = from; k <= to; ++k) {
      const int row = with_ends ? k + 1 : k;
      put_basis_row(m, c, last, row, ub[static_cast<std::size_t>(k)], span);
      if (with_ends) rhs[static_cast<std::size_t>(row)] = q[static_cast<std::size_t>(k)];
    }
  });
  if (with_ends) {
    const double first = c.knots[p + 1];
    const double last_knot = c.knots[controls - 1];  // u_{m-p-1} with m the last knot index
    for (const int r : {0, 1, n + 1, n + 2}) m.start_row(r, r == 1 ? 0 : r);
    m.at(0, 0) = 1.0;
    rhs[0] = q[0];
    m.at(1, 0) = -1.0;
    m.at(1, 1) = 1.0;
    rhs[1] = (first / p) * *options.start_derivative;
    m.at(n + 1, n + 1) = -1.0;
    m.at(n + 1, n + 2) = 1.0;
    rhs[n + 1] = ((1.0 - last_knot) / p) * *options.end_derivative;
    m.at(n + 2, n + 2) = 1.0;
    rhs[n + 2] = q[n];
  }
  m.solve(rhs);
  c.points = std::move(rhs);
  return result;
}

}  // namespace knitc::nurbs
