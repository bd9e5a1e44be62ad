// Global curve interpolation through data points (P&T A9.1, and section 9.2.2 for end
// derivatives). The system matrix is banded: row k has non-zeros only in the p + 1
// columns of its knot span, so a banded LU without pivoting solves it in O(n p^2).
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

// A square matrix stored by diagonals: entry (r, c) with -lower <= c - r <= upper.
class BandMatrix {
 public:
  // The cells are left unset: each row is cleared (clear_row) by whoever fills it, so a
  // garment's rows are first written in parallel, not zeroed by one thread first.
  BandMatrix(int size, int lower, int upper)
      : n_(size), lower_(lower), upper_(upper),
        cells_(new double[static_cast<std::size_t>(size) * static_cast<std::size_t>(lower + upper + 1)]) {}

  void clear_row(int r) {
    double* first = cells_.get() + static_cast<std::size_t>(r) * static_cast<std::size_t>(lower_ + upper_ + 1);
    std::fill(first, first + lower_ + upper_ + 1, 0.0);
  }

  double& at(int r, int c) {
    if (c - r < -lower_ || c - r > upper_) throw std::logic_error("nurbs: entry outside the band");
    return cells_[static_cast<std::size_t>(r) * static_cast<std::size_t>(lower_ + upper_ + 1) + static_cast<std::size_t>(c - r + lower_)];
  }

  // In-place LU without pivoting, then solves for every right-hand side column. (The
  // entries read inside the band without at()'s check: a garment's curve is a million
  // rows.)
  void solve(std::vector<Point>& rhs) {
    for (int k = 0; k < n_; ++k) {
      const double pivot = cell(k, k);
      if (std::abs(pivot) < 1e-300) throw std::invalid_argument("nurbs: singular interpolation system");
      const int last_c = std::min(n_ - 1, k + upper_);
      for (int r = k + 1; r <= std::min(n_ - 1, k + lower_); ++r) {
        const double f = cell(r, k) / pivot;
        if (f == 0.0) continue;
        cell(r, k) = f;
        double* row = row_of(r);
        const double* top = row_of(k);
        for (int c = k + 1; c <= last_c; ++c) row[c] -= f * top[c];
        rhs[static_cast<std::size_t>(r)] -= f * rhs[static_cast<std::size_t>(k)];
      }
    }
    for (int k = n_ - 1; k >= 0; --k) {
      Point v = rhs[static_cast<std::size_t>(k)];
      const double* row = row_of(k);
      for (int c = k + 1; c <= std::min(n_ - 1, k + upper_); ++c) v -= row[c] * rhs[static_cast<std::size_t>(c)];
      rhs[static_cast<std::size_t>(k)] = v / cell(k, k);
    }
  }

 private:
  // (r, c) inside the band, unchecked; row_of(r)[c] is (r, c) for any c in the band (the
  // row's cells, shifted so a column indexes them).
  double* row_of(int r) { return cells_.get() + static_cast<std::size_t>(r) * static_cast<std::size_t>(lower_ + upper_) + static_cast<std::size_t>(lower_); }
  double& cell(int r, int c) { return row_of(r)[c]; }
  int n_, lower_, upper_;
  std::unique_ptr<double[]> cells_;
};

std::vector<double> data_parameters(std::span<const Point> q, Parametrisation kind) {
  const std::size_t n = q.size() - 1;
  std::vector<double> step(n + 1, 0.0);
  double total = 0.0;
  for (std::size_t k = 1; k <= n; ++k) {
    const double chord = glm::distance(q[k], q[k - 1]);
    if (!(chord > 0.0)) throw std::invalid_argument("nurbs: two consecutive data points coincide");
    step[k] = kind == Parametrisation::centripetal ? std::sqrt(chord) : chord;
    total += step[k];
  }
  std::vector<double> u(n + 1, 0.0);
  for (std::size_t k = 1; k < n; ++k) u[k] = u[k - 1] + step[k] / total;
  u[n] = 1.0;
  return u;
}

// Fills row `row` of the matrix with the basis functions at u. span: the knot span found
// for the last row (the rows' parameters ascend), walked on to u's.
void put_basis_row(BandMatrix& m, const Curve& c, int last, int row, double u, int& span) {
  while (span < last && c.knots[static_cast<std::size_t>(span) + 1] <= u) ++span;
  // find_span's span (the curve's control points are not made yet: it cannot be asked).
  assert(c.knots[static_cast<std::size_t>(span)] <= u && (span == last || u < c.knots[static_cast<std::size_t>(span) + 1]));
  BasisTable N;
  basis_derivatives(c, span, u, 0, N);
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

  // The band: the widest a data row's entries (its span's p + 1 columns) lie from its
  // diagonal, found by walking the spans once: p either side with averaged knots, where
  // p + 1 was allowed (a garment's million-point curve's matrix was most of this stage's
  // memory). Each block of rows starts its walk where the walk found its first span.
  constexpr int block = 16384;
  const int first_row = with_ends ? 1 : 0, last_row = with_ends ? n - 1 : n;  // data rows' k
  const int rows = std::max(0, last_row - first_row + 1);
  const int blocks = (rows + block - 1) / block;
  std::vector<int> block_span(static_cast<std::size_t>(blocks), p);
  int lower = 1, upper = 1;  // the end derivatives' rows
  {
    int walk = p;
    for (int k = first_row; k <= last_row; ++k) {
      while (walk < last && c.knots[static_cast<std::size_t>(walk) + 1] <= ub[k]) ++walk;
      if ((k - first_row) % block == 0) block_span[static_cast<std::size_t>((k - first_row) / block)] = walk;
      const int row = with_ends ? k + 1 : k;
      lower = std::max(lower, row - (walk - p));
      upper = std::max(upper, walk - row);
    }
  }
  BandMatrix m(controls, lower, upper);
  std::vector<Point> rhs = with_ends ? std::vector<Point>(static_cast<std::size_t>(controls)) : std::vector<Point>(q.begin(), q.end());
  parallel_for(static_cast<std::size_t>(blocks), thread_count(options.threads), [&](std::size_t b) {
    int span = block_span[b];
    const int from = first_row + static_cast<int>(b) * block, to = std::min(last_row, from + block - 1);
    for (int k = from; k <= to; ++k) {
      const int row = with_ends ? k + 1 : k;
      m.clear_row(row);
      put_basis_row(m, c, last, row, ub[static_cast<std::size_t>(k)], span);
      if (with_ends) rhs[static_cast<std::size_t>(row)] = q[static_cast<std::size_t>(k)];
    }
  });
  if (with_ends) {
    const double first = c.knots[p + 1];
    const double last_knot = c.knots[controls - 1];  // u_{m-p-1} with m the last knot index
    for (const int r : {0, 1, n + 1, n + 2}) m.clear_row(r);
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
