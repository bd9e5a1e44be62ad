// Evaluation of clamped NURBS curves: knot spans, basis function derivatives (A2.1,
// A2.3) and rational curve derivatives (A3.2 on homogeneous points, then A4.2).
#include "nurbs.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace knitc::nurbs {

bool is_valid(const Curve& c) {
  const int p = c.degree;
  const std::size_t n = c.points.size();
  if (p < 1 || p > max_degree || n < static_cast<std::size_t>(p) + 1) return false;
  if (c.knots.size() != n + static_cast<std::size_t>(p) + 1) return false;
  if (!c.weights.empty() && c.weights.size() != n) return false;
  if (!std::is_sorted(c.knots.begin(), c.knots.end())) return false;
  for (int i = 0; i <= p; ++i) {
    if (c.knots[i] != c.knots[0] || c.knots[c.knots.size() - 1 - i] != c.knots.back()) return false;
  }
  if (!(c.knots.front() < c.knots.back())) return false;
  return std::all_of(c.weights.begin(), c.weights.end(), [](double w) { return w > 0; });
}

int find_span(const Curve& c, double u) {
  const int p = c.degree;
  const int n = static_cast<int>(c.points.size()) - 1;
  const auto& U = c.knots;
  if (u >= U[n + 1]) return n;
  if (u <= U[p]) return p;
  // Binary search for U[span] <= u < U[span + 1].
  int low = p, high = n + 1;
  int mid = (low + high) / 2;
  while (u < U[mid] || u >= U[mid + 1]) {
    if (u < U[mid]) high = mid; else low = mid;
    mid = (low + high) / 2;
  }
  return mid;
}

int next_span(const Curve& c, int from, double u) {
  const int p = c.degree;
  const int n = static_cast<int>(c.points.size()) - 1;
  const auto& U = c.knots;
  if (u >= U[static_cast<std::size_t>(n + 1)] || u <= U[static_cast<std::size_t>(p)] || from < p || from > n ||
      u < U[static_cast<std::size_t>(from)])
    return find_span(c, u);
  // U[s] <= u holds from `from` on; the span is the first s with u < U[s + 1].
  for (int s = from, steps = 0; steps < 16; ++s, ++steps)
    if (u < U[static_cast<std::size_t>(s) + 1]) return s;
  return find_span(c, u);
}

namespace {

// The algorithm with the degree known when compiled (P > 0) or read from the curve (P =
// 0): the cubic, knitc's every curve, gets its loops unrolled, with the same operations in
// the same order, so the same bits.
template <int P>
void basis_derivatives_of(const Curve& c, int span, double u, int order, BasisTable& ders) {
  const int p = P > 0 ? P : c.degree;
  assert(p <= max_degree && order <= max_order);
  const auto& U = c.knots;
  double ndu[max_degree + 1][max_degree + 1];
  double left[max_degree + 1], right[max_degree + 1];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[span + 1 - j];
    right[j] = U[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // knot differences (lower triangle)
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;  // basis functions (upper triangle)
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
  for (int k = p + 1; k <= order; ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] = 0.0;
  }
  const int top = std::min(order, p);
  double a[2][max_degree + 1];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= top; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  double factor = p;
  for (int k = 1; k <= top; ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] *= factor;
    factor *= (p - k);
  }
}

}  // namespace

void basis_derivatives(const Curve& c, int span, double u, int order, BasisTable& ders) {
  if (c.degree == 3) basis_derivatives_of<3>(c, span, u, order, ders);
  else basis_derivatives_of<0>(c, span, u, order, ders);
}

namespace {

// A non-rational cubic's derivatives: the basis unrolled, no weights.
std::array<Point, max_order + 1> cubic_derivatives(const Curve& c, int span, double u, int order) {
  BasisTable N;
  basis_derivatives_of<3>(c, span, u, order, N);
  std::array<Point, max_order + 1> A{};
  for (int k = 0; k <= order; ++k) {
    Point a(0.0);
    for (int j = 0; j <= 3; ++j) a += (N[k][j] * 1.0) * c.points[static_cast<std::size_t>(span - 3 + j)];
    A[k] = a;
  }
  return A;
}

}  // namespace

std::array<Point, max_order + 1> derivatives(const Curve& c, double u, int order) { return derivatives(c, find_span(c, u), u, order); }

std::array<Point, max_order + 1> derivatives(const Curve& c, int span, double u, int order) {
  assert(order >= 0 && order <= max_order);
  // (u may round a few ulps past either end of the span, as a quadrature point on an
  // interval of a few ulps does: there the neighbouring spans' polynomials agree.)
  [[maybe_unused]] const double slack = 64.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(u));
  assert(span == find_span(c, u) ||
         (span >= c.degree && static_cast<std::size_t>(span) + 1 < c.knots.size() &&
          c.knots[static_cast<std::size_t>(span)] - slack <= u && u <= c.knots[static_cast<std::size_t>(span) + 1] + slack));
  const int p = c.degree;
  if (p == 3 && c.weights.empty()) return cubic_derivatives(c, span, u, order);
  BasisTable N;
  basis_derivatives(c, span, u, order, N);

  // Derivatives of the homogeneous curve: A^(k) = sum w_i P_i N_i^(k), w^(k) = sum w_i N_i^(k).
  std::array<Point, max_order + 1> A{};
  std::array<double, max_order + 1> w{};
  const bool rational = !c.weights.empty();
  for (int k = 0; k <= order; ++k) {
    Point a(0.0);
    double wk = 0.0;
    for (int j = 0; j <= p; ++j) {
      const int i = span - p + j;
      const double wi = rational ? c.weights[i] : 1.0;
      a += (N[k][j] * wi) * c.points[i];
      wk += N[k][j] * wi;
    }
    A[k] = a;
    w[k] = wk;
  }
  if (!rational) return A;  // w = 1, w' = w'' = 0: the B-spline's own derivatives

  // A4.2: C^(k) = (A^(k) - sum_{i=1..k} binom(k,i) w^(i) C^(k-i)) / w.
  static constexpr int binom[max_order + 1][max_order + 1] = {
      {1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  std::array<Point, max_order + 1> C{};
  for (int k = 0; k <= order; ++k) {
    Point v = A[k];
    for (int i = 1; i <= k; ++i) v -= (binom[k][i] * w[i]) * C[k - i];
    C[k] = v / w[0];
  }
  return C;
}

Point evaluate(const Curve& c, double u) { return derivatives(c, u, 0)[0]; }

Span::Span(const Curve& c, int span) : curve_(&c), span_(span) {
  assert(span >= c.degree && static_cast<std::size_t>(span) + 1 < c.knots.size());
  if (c.degree != 3 || !c.weights.empty()) return;
  // The Taylor coefficients at the span's first knot: C^(k)(a) / k!.
  start_ = c.knots[static_cast<std::size_t>(span)];
  const auto d = cubic_derivatives(c, span, start_, 3);
  c_[0] = d[0];
  c_[1] = d[1];
  c_[2] = 0.5 * d[2];
  c_[3] = (1.0 / 6.0) * d[3];
  power_ = true;
}

std::array<Point, max_order + 1> Span::derivatives(double u, int order) const {
  assert(order >= 0 && order <= max_order);
  if (!power_) return nurbs::derivatives(*curve_, span_, u, order);
  const double t = u - start_;
  std::array<Point, max_order + 1> d{};
  d[0] = c_[0] + t * (c_[1] + t * (c_[2] + t * c_[3]));
  if (order >= 1) d[1] = c_[1] + t * (2.0 * c_[2] + t * (3.0 * c_[3]));
  if (order >= 2) d[2] = 2.0 * c_[2] + t * (6.0 * c_[3]);
  if (order >= 3) d[3] = 6.0 * c_[3];
  return d;
}

}  // namespace knitc::nurbs
