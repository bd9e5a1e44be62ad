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

// Each step is made in parallel into the parameters' own array, then summed and
// accumulated in order: the same bits as one pass, for any thread count (a garment's
// 1.8 million steps took 18 ms on one thread).
std::vector<double> data_parameters(std::span<const Point> q, Parametrisation kind, int threads) {
  const std::size_t n = q.size() - 1;
  std::vector<double> u(n + 1);
  constexpr std::size_t block = 65536;
  parallel_for((n + block - 1) / block, threads, [&](std::size_t b) {
    for (std::size_t k = 1 + b * block, to = std::min(n, (b + 1) * block); k <= to; ++k) {
      const double chord = glm::distance(q[k], q[k - 1]);
      u[k] = kind == Parametrisation::centripetal ? std::sqrt(chord) : chord;
    }
  });
  double total = 0.0;
  for (std::size_t k = 1; k <= n; ++k) {
    if (!(u[k] > 0.0)) throw std::invalid_argument("nurbs: two consecutive data points coincide");
    total += u[k];
  }
  u[0] = 0.0;
  for (std::size_t k = 1; k < n; ++k) u[k] = u[k - 1] + u[k] / total;
  u[n] = 1.0;
  return u;
}

// The knot span holding u (the control points are not made yet, so find_span cannot be
// asked): the last s in [p, last] with knots[s] <= u.
int span_of(const Curve& c, int last, double u) {
  const auto from = c.knots.begin() + c.degree, to = c.knots.begin() + last + 1;
  return std::max(c.degree, static_cast<int>(std::upper_bound(from, to, u) - c.knots.begin()) - 1);
}

// Fills row `row` of the system, as row row - lo of `m` whose columns start at lo (those
// past hi dropped), with the basis functions at u. span: the knot span found for the
// last row (the rows' parameters ascend), walked on to u's.
void put_basis_row(ProfileMatrix& m, const Curve& c, int last, int row, double u, int& span, int lo, int hi) {
  while (span < last && c.knots[static_cast<std::size_t>(span) + 1] <= u) ++span;
  assert(span == span_of(c, last, u));
  BasisTable N;
  basis_derivatives(c, span, u, 0, N);
  const int first = span - c.degree;
  m.start_row(row - lo, std::max(first, lo) - lo);
  for (int j = 0; j <= c.degree; ++j)
    if (first + j >= lo && first + j < hi) m.at(row - lo, first + j - lo) = N[0][j];
}

}  // namespace

Interpolant interpolate(std::span<const Point> q, const InterpolationOptions& options) {
  if (q.size() < 2) throw std::invalid_argument("nurbs: interpolation needs at least two data points");
  const int n = static_cast<int>(q.size()) - 1;
  const bool with_ends = options.start_derivative.has_value() || options.end_derivative.has_value();
  if (with_ends && !(options.start_derivative && options.end_derivative))
    throw std::invalid_argument("nurbs: give both end derivatives or neither");

  Interpolant result;
  result.parameters = data_parameters(q, options.parametrisation, thread_count(options.threads));
  const auto& ub = result.parameters;
  Curve& c = result.curve;

  // Degree: cubic, lowered for too few points; end derivatives add two control points.
  const int controls = with_ends ? n + 3 : n + 1;
  const int p = std::min(3, controls - 1);
  c.degree = p;
  c.knots.assign(static_cast<std::size_t>(controls + p + 1), 0.0);
  for (int i = 0; i <= p; ++i) c.knots[c.knots.size() - 1 - i] = 1.0;
  if (!with_ends) {
    constexpr int block = 65536;  // eq. 9.8, by blocks of knots in parallel
    parallel_for(static_cast<std::size_t>(std::max(0, n - p) + block - 1) / block, thread_count(options.threads), [&](std::size_t b) {
      for (int j = 1 + static_cast<int>(b) * block, to = std::min(n - p, (static_cast<int>(b) + 1) * block); j <= to; ++j) {
        double s = 0.0;
        for (int i = j; i <= j + p - 1; ++i) s += ub[static_cast<std::size_t>(i)];
        c.knots[static_cast<std::size_t>(j + p)] = s / p;
      }
    });
  } else {
    for (int j = 0; j <= n - p + 1; ++j) {  // eq. 9.22
      double s = 0.0;
      for (int i = j; i <= j + p - 1; ++i) s += ub[std::min(i, n)];
      c.knots[j + p + 1] = s / p;
    }
  }
  const int last = controls - 1;  // the last control point's index

  // Rows lo to hi - 1 of the system, as rows 0 to hi - lo - 1 of m and rhs (the columns
  // outside [lo, hi) dropped), the data rows filled in blocks on `threads`.
  const int first_row = with_ends ? 1 : 0, last_row = with_ends ? n - 1 : n;  // data rows' k
  const int shift = with_ends ? 1 : 0;                                        // a data row's row
  auto fill = [&](ProfileMatrix& m, std::vector<Point>& rhs, int lo, int hi, int threads) {
    constexpr int block = 16384;
    const int k_from = std::max(first_row, lo - shift), k_to = std::min(last_row, hi - 1 - shift);
    const int rows = std::max(0, k_to - k_from + 1);
    parallel_for(static_cast<std::size_t>((rows + block - 1) / block), threads, [&](std::size_t b) {
      const int from = k_from + static_cast<int>(b) * block, to = std::min(k_to, from + block - 1);
      int span = span_of(c, last, ub[static_cast<std::size_t>(from)]);
      for (int k = from; k <= to; ++k) {
        put_basis_row(m, c, last, k + shift, ub[static_cast<std::size_t>(k)], span, lo, hi);
        rhs[static_cast<std::size_t>(k + shift - lo)] = q[static_cast<std::size_t>(k)];
      }
    });
    if (!with_ends) return;
    const double first = c.knots[p + 1];
    const double last_knot = c.knots[controls - 1];  // u_{m-p-1} with m the last knot index
    auto row = [&](int r, std::initializer_list<std::pair<int, double>> cells, const Point& value) {
      if (r < lo || r >= hi) return;
      m.start_row(r - lo, std::max(r == 1 ? 0 : r, lo) - lo);
      for (const auto& [col, v] : cells)
        if (col >= lo && col < hi) m.at(r - lo, col - lo) = v;
      rhs[static_cast<std::size_t>(r - lo)] = value;
    };
    row(0, {{0, 1.0}}, q[0]);
    row(1, {{0, -1.0}, {1, 1.0}}, (first / p) * *options.start_derivative);
    row(n + 1, {{n + 1, -1.0}, {n + 2, 1.0}}, ((1.0 - last_knot) / p) * *options.end_derivative);
    row(n + 2, {{n + 2, 1.0}}, q[static_cast<std::size_t>(n)]);
  };

  // A long curve's system is solved in windows, in parallel: each solves its rows with
  // `halo` more either side, its unknowns past them taken as 0, and keeps the middle. A
  // control point's pull on another dies off as about 0.27^(rows between) (cubic
  // interpolation's system is totally positive and near diagonally dominant), so past 128
  // rows it is under any double's rounding: the same curve to rounding, and the same bits
  // for any thread count, since the windows follow from the length alone. A window's
  // system stays in the cache and is made afresh by the thread that solves it.
  constexpr int window = 65536, halo = 128;
  if (controls <= 2 * window) {
    ProfileMatrix m(controls, p);
    std::vector<Point> rhs(static_cast<std::size_t>(controls));
    fill(m, rhs, 0, controls, thread_count(options.threads));
    m.solve(rhs);
    c.points = std::move(rhs);
    return result;
  }
  c.points.resize(static_cast<std::size_t>(controls));
  const int windows = (controls + window - 1) / window;
  parallel_for(static_cast<std::size_t>(windows), thread_count(options.threads), [&](std::size_t w) {
    const int a = static_cast<int>(w) * window, b = std::min(controls, a + window);
    const int lo = std::max(0, a - halo), hi = std::min(controls, b + halo);
    ProfileMatrix m(hi - lo, p);
    std::vector<Point> rhs(static_cast<std::size_t>(hi - lo));
    fill(m, rhs, lo, hi, 1);
    m.solve(rhs);
    std::copy(rhs.begin() + (a - lo), rhs.begin() + (b - lo), c.points.begin() + a);
  });
  return result;
}

}  // namespace knitc::nurbs
