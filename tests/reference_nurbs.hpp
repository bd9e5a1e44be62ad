// An independent, deliberately plain reference implementation of the NURBS core, for
// tests only. It shares no code with compiler/nurbs/ and uses different algorithms on
// purpose, so that the two agreeing is evidence for both:
//  - basis functions by the Cox-de Boor recursion (P&T eq. 2.5) instead of A2.2/A2.3,
//    and their derivatives by the recursion of P&T eq. 2.9;
//  - curve points as a plain sum over ALL basis functions, not just the p + 1 of a span;
//  - the interpolation system as a dense matrix solved by Gaussian elimination with
//    partial pivoting, instead of a banded LU.
// Speed is no concern here: everything is O(n) per basis function sum and O(n^3) per
// interpolation. Points are glm::dvec3. Header-only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "nurbs/nurbs.hpp"

namespace knitc::reference {

// The parameter of each data point, in [0, 1]: ubar_0 = 0, ubar_n = 1 and steps
// proportional to the chord |q_k - q_(k-1)| (chord length, P&T eq. 9.5) or to its square
// root (centripetal = true, P&T eq. 9.6). Computed as running sum / total. Throws
// std::invalid_argument for fewer than two points or two equal consecutive points.
inline std::vector<double> parameters(const std::vector<glm::dvec3>& q, bool centripetal) {
  if (q.size() < 2) throw std::invalid_argument("reference: need at least two points");
  std::vector<double> running(q.size(), 0.0);
  for (std::size_t k = 1; k < q.size(); ++k) {
    const double chord = glm::length(q[k] - q[k - 1]);
    if (!(chord > 0.0)) throw std::invalid_argument("reference: equal consecutive points");
    running[k] = running[k - 1] + (centripetal ? std::sqrt(chord) : chord);
  }
  const double total = running.back();
  std::vector<double> u(q.size());
  for (std::size_t k = 0; k < q.size(); ++k) u[k] = running[k] / total;
  u.front() = 0.0;
  u.back() = 1.0;
  return u;
}

// The clamped knot vector of degree p by averaging the parameters ubar_0..ubar_n
// (P&T eq. 9.8): p + 1 copies of ubar_0, then u_(j+p) = (ubar_j + ... + ubar_(j+p-1)) / p
// for j = 1..n-p, then p + 1 copies of ubar_n. Size ubar.size() + p + 1.
inline std::vector<double> averaged_knots(const std::vector<double>& ubar, int p) {
  const int n = static_cast<int>(ubar.size()) - 1;
  std::vector<double> U;
  for (int i = 0; i <= p; ++i) U.push_back(ubar.front());
  for (int j = 1; j <= n - p; ++j) {
    double s = 0.0;
    for (int i = j; i <= j + p - 1; ++i) s += ubar[static_cast<std::size_t>(i)];
    U.push_back(s / p);
  }
  for (int i = 0; i <= p; ++i) U.push_back(ubar.back());
  return U;
}

// The clamped knot vector of degree p for interpolation with both end derivatives given
// (P&T eq. 9.22): p + 1 copies of ubar_0, then u_(j+p+1) = (ubar_j + ... + ubar_(j+p-1)) / p
// for j = 0..n-p+1, then p + 1 copies of ubar_n. Size ubar.size() + 2 + p + 1.
inline std::vector<double> averaged_knots_with_end_derivatives(const std::vector<double>& ubar, int p) {
  const int n = static_cast<int>(ubar.size()) - 1;
  std::vector<double> U;
  for (int i = 0; i <= p; ++i) U.push_back(ubar.front());
  for (int j = 0; j <= n - p + 1; ++j) {
    double s = 0.0;
    for (int i = j; i <= j + p - 1; ++i) s += ubar[static_cast<std::size_t>(i)];
    U.push_back(s / p);
  }
  for (int i = 0; i <= p; ++i) U.push_back(ubar.back());
  return U;
}

// The B-spline basis function N_(i,p)(u) on the knot vector U by the Cox-de Boor
// recursion, with 0/0 = 0. N_(i,0) is 1 on [U_i, U_(i+1)) and 0 elsewhere, except that at
// u == U.back() the last non-empty interval counts as closed (so the basis still sums to
// one at the end of a clamped knot vector).
inline double basis(int i, int p, double u, const std::vector<double>& U) {
  const auto at = [&U](int k) { return U[static_cast<std::size_t>(k)]; };
  // Local support: N_(i,p) vanishes outside [U_i, U_(i+p+1)] (this only saves time).
  if (u < at(i) || u > at(i + p + 1)) return 0.0;
  if (p == 0) {
    if (at(i) <= u && u < at(i + 1)) return 1.0;
    return (u == U.back() && at(i) < at(i + 1) && at(i + 1) == U.back()) ? 1.0 : 0.0;
  }
  double value = 0.0;
  const double d1 = at(i + p) - at(i);
  if (d1 != 0.0) value += (u - at(i)) / d1 * basis(i, p - 1, u, U);
  const double d2 = at(i + p + 1) - at(i + 1);
  if (d2 != 0.0) value += (at(i + p + 1) - u) / d2 * basis(i + 1, p - 1, u, U);
  return value;
}

// The k-th derivative of N_(i,p) at u (P&T eq. 2.9, applied recursively):
// N^(k)_(i,p) = p (N^(k-1)_(i,p-1) / (U_(i+p) - U_i) - N^(k-1)_(i+1,p-1) / (U_(i+p+1) - U_(i+1))),
// terms with a zero denominator dropped. Zero for k > p. At a knot this is the derivative
// from the right (from the left at u == U.back()), matching basis().
inline double basis_derivative(int i, int p, int k, double u, const std::vector<double>& U) {
  if (k == 0) return basis(i, p, u, U);
  if (k > p) return 0.0;
  const auto at = [&U](int j) { return U[static_cast<std::size_t>(j)]; };
  double value = 0.0;
  const double d1 = at(i + p) - at(i);
  if (d1 != 0.0) value += basis_derivative(i, p - 1, k - 1, u, U) / d1;
  const double d2 = at(i + p + 1) - at(i + 1);
  if (d2 != 0.0) value -= basis_derivative(i + 1, p - 1, k - 1, u, U) / d2;
  return p * value;
}

// Solves the dense system A x = b (A square, one glm::dvec3 right-hand side per row) by
// Gaussian elimination with partial pivoting. Throws std::invalid_argument on a zero
// pivot (a singular matrix).
inline std::vector<glm::dvec3> solve(std::vector<std::vector<double>> A, std::vector<glm::dvec3> b) {
  const std::size_t n = A.size();
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t best = col;
    for (std::size_t r = col + 1; r < n; ++r)
      if (std::abs(A[r][col]) > std::abs(A[best][col])) best = r;
    if (A[best][col] == 0.0) throw std::invalid_argument("reference: singular matrix");
    std::swap(A[col], A[best]);
    std::swap(b[col], b[best]);
    for (std::size_t r = col + 1; r < n; ++r) {
      const double f = A[r][col] / A[col][col];
      for (std::size_t c = col; c < n; ++c) A[r][c] -= f * A[col][c];
      b[r] -= f * b[col];
    }
  }
  std::vector<glm::dvec3> x(n);
  for (std::size_t r = n; r-- > 0;) {
    glm::dvec3 s = b[r];
    for (std::size_t c = r + 1; c < n; ++c) s -= A[r][c] * x[c];
    x[r] = s / A[r][r];
  }
  return x;
}

// The point C(u) of a knitc::nurbs::Curve (only its fields are read), as the plain sum
// over all control points: sum w_i P_i N_(i,p)(u) / sum w_i N_(i,p)(u), with w_i = 1 when
// the curve has no weights. u is clamped to [knots.front(), knots.back()].
inline glm::dvec3 point(const knitc::nurbs::Curve& c, double u) {
  u = std::clamp(u, c.knots.front(), c.knots.back());
  glm::dvec3 num(0.0);
  double den = 0.0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const double w = c.weights.empty() ? 1.0 : c.weights[i];
    const double N = basis(static_cast<int>(i), c.degree, u, c.knots);
    num += (w * N) * c.points[i];
    den += w * N;
  }
  return num / den;
}

// The k-th derivative (k = 0..3) of a knitc::nurbs::Curve at u, from the basis function
// derivatives above: for a non-rational curve sum P_i N^(k)_i; for a rational one the
// homogeneous derivatives A^(j) = sum w_i P_i N^(j)_i, w^(j) = sum w_i N^(j)_i and the
// Leibniz rule C^(k) = (A^(k) - sum_(j=1..k) binom(k, j) w^(j) C^(k-j)) / w. u is clamped
// to the domain.
inline glm::dvec3 derivative(const knitc::nurbs::Curve& c, double u, int k) {
  if (k < 0 || k > 3) throw std::invalid_argument("reference: derivative order must be 0..3");
  u = std::clamp(u, c.knots.front(), c.knots.back());
  glm::dvec3 A[4] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
  double w[4] = {0.0, 0.0, 0.0, 0.0};
  for (int j = 0; j <= k; ++j) {
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      const double wi = c.weights.empty() ? 1.0 : c.weights[i];
      const double N = basis_derivative(static_cast<int>(i), c.degree, j, u, c.knots);
      A[j] += (wi * N) * c.points[i];
      w[j] += wi * N;
    }
  }
  if (c.weights.empty()) return A[k];  // non-rational: w = 1 and its derivatives vanish
  const double binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  glm::dvec3 C[4];
  for (int j = 0; j <= k; ++j) {
    glm::dvec3 v = A[j];
    for (int i = 1; i <= j; ++i) v -= (binom[j][i] * w[i]) * C[j - i];
    C[j] = v / w[0];
  }
  return C[k];
}

// A non-rational interpolating curve: clamped knot vector, control points, and the
// parameter of each data point. Its degree is knots.size() - control.size() - 1 (also
// stored in `degree`).
struct RefInterpolant {
  std::vector<double> knots;
  std::vector<glm::dvec3> control;
  std::vector<double> params;
  int degree = 3;
};

// Global interpolation through q (P&T section 9.2.1): degree min(3, q.size() - 1),
// parameters by parameters(q, centripetal), knots by averaged_knots, and control points
// from the dense (n+1) x (n+1) system N_(i,p)(ubar_k) P_i = q_k solved by solve().
// Throws std::invalid_argument like parameters().
inline RefInterpolant interpolate(const std::vector<glm::dvec3>& q, bool centripetal) {
  RefInterpolant r;
  r.params = parameters(q, centripetal);
  const std::size_t count = q.size();
  r.degree = std::min(3, static_cast<int>(count) - 1);
  r.knots = averaged_knots(r.params, r.degree);
  std::vector<std::vector<double>> A(count, std::vector<double>(count, 0.0));
  for (std::size_t k = 0; k < count; ++k)
    for (std::size_t i = 0; i < count; ++i) A[k][i] = basis(static_cast<int>(i), r.degree, r.params[k], r.knots);
  r.control = solve(std::move(A), q);
  return r;
}

// Cubic global interpolation through q with the first derivatives d0 = C'(0) and
// d1 = C'(1) given (P&T section 9.2.2): knots by averaged_knots_with_end_derivatives,
// n + 3 control points from the dense system made of the n + 1 interpolation rows and
// the two derivative rows sum_i N'_(i,3)(end) P_i = d. Throws like parameters().
inline RefInterpolant interpolate_with_end_derivatives(const std::vector<glm::dvec3>& q, bool centripetal,
                                                       const glm::dvec3& d0, const glm::dvec3& d1) {
  RefInterpolant r;
  r.params = parameters(q, centripetal);
  r.degree = 3;
  r.knots = averaged_knots_with_end_derivatives(r.params, r.degree);
  const std::size_t count = q.size() + 2;
  std::vector<std::vector<double>> A;
  std::vector<glm::dvec3> b;
  const auto row = [&](double u, int order) {
    std::vector<double> a(count);
    for (std::size_t i = 0; i < count; ++i) a[i] = basis_derivative(static_cast<int>(i), r.degree, order, u, r.knots);
    return a;
  };
  for (std::size_t k = 0; k < q.size(); ++k) {
    A.push_back(row(r.params[k], 0));
    b.push_back(q[k]);
  }
  A.push_back(row(r.params.front(), 1));
  b.push_back(d0);
  A.push_back(row(r.params.back(), 1));
  b.push_back(d1);
  r.control = solve(std::move(A), std::move(b));
  return r;
}

// The point of a RefInterpolant at u (clamped to [0, 1]), as the plain sum
// sum_i P_i N_(i,p)(u) over all control points.
inline glm::dvec3 point(const RefInterpolant& r, double u) {
  u = std::clamp(u, r.knots.front(), r.knots.back());
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < r.control.size(); ++i)
    sum += basis(static_cast<int>(i), r.degree, u, r.knots) * r.control[i];
  return sum;
}

// The same RefInterpolant as a knitc::nurbs::Curve (non-rational, no weights), e.g. to
// compare knots and control points field by field.
inline knitc::nurbs::Curve to_curve(const RefInterpolant& r) {
  knitc::nurbs::Curve c;
  c.degree = r.degree;
  c.knots = r.knots;
  c.points = r.control;
  return c;
}

}  // namespace knitc::reference
