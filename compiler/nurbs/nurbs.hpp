// The NURBS core: clamped rational B-spline curves, their evaluation with derivatives,
// and global interpolation through data points (Piegl & Tiller, The NURBS Book, 2nd ed.,
// chapters 2, 4 and 9). Depends on GLM and the standard library only.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace knitc::nurbs {

using Point = glm::dvec3;

// A clamped NURBS curve C(u), u in [knots.front(), knots.back()].
// Invariants (checked by is_valid): degree >= 1; points.size() >= degree + 1;
// knots.size() == points.size() + degree + 1, non-decreasing, first and last values
// repeated degree + 1 times; weights empty (all 1: a non-rational B-spline) or one
// positive weight per control point.
struct Curve {
  int degree = 3;
  std::vector<double> knots;
  std::vector<Point> points;
  std::vector<double> weights;
};

bool is_valid(const Curve& curve);

// The knot span index i with knots[i] <= u < knots[i+1] (A2.1); u is clamped to the
// curve's domain, and u at the domain's end falls in the last non-empty span.
int find_span(const Curve& curve, double u);
// The same, found by walking up from span `from` (a caller whose parameters ascend, the
// next a few knots on): a few steps, not a search of the whole knot vector. Any from.
int next_span(const Curve& curve, int from, double u);

// Basis functions N_{span-p..span, p}(u) and their derivatives up to `order` (A2.3):
// out[k][j] is the k-th derivative of N_{span-p+j,p} at u. order <= max_order.
inline constexpr int max_degree = 7;
inline constexpr int max_order = 3;
using BasisTable = std::array<std::array<double, max_degree + 1>, max_order + 1>;
void basis_derivatives(const Curve& curve, int span, double u, int order, BasisTable& out);

// C(u) and its derivatives d^k C / du^k for k = 0..order (order <= 3), rational
// derivatives by A4.2. Derivatives above the degree are zero.
std::array<Point, max_order + 1> derivatives(const Curve& curve, double u, int order);
// The same, in a span already found: u in [knots[span], knots[span + 1]] (a few ulps
// past an end allowed, as rounding puts a point there), or find_span(curve, u)'s span (a
// caller that evaluates many points inside one knot span finds it once).
std::array<Point, max_order + 1> derivatives(const Curve& curve, int span, double u, int order);
Point evaluate(const Curve& curve, double u);

// One knot span of a curve, made once and evaluated many times (sampling, lengths,
// frames evaluate a dozen points a span): a non-rational cubic's span, knitc's every
// curve, is turned into power form about its first knot, C(a + t) = c0 + c1 t + c2 t^2
// + c3 t^3, so a point and its derivatives cost a few multiply-adds instead of the basis
// functions' recurrence; any other curve's span is evaluated by derivatives(). u in the
// span [knots[span], knots[span + 1]] as for derivatives(curve, span, u, order); agrees
// with it to rounding. Keeps a reference to the curve.
class Span {
 public:
  Span(const Curve& curve, int span);
  int index() const { return span_; }
  // Whether u is in [knots[span], knots[span + 1]): find_span's span for it (but at the
  // domain's very end).
  bool holds(double u) const {
    return curve_->knots[static_cast<std::size_t>(span_)] <= u && u < curve_->knots[static_cast<std::size_t>(span_) + 1];
  }
  std::array<Point, max_order + 1> derivatives(double u, int order) const;
  double speed(double u) const;      // |C'(u)|
  double curvature(double u) const;  // as curvature(curve, span, u)

 private:
  const Curve* curve_;
  int span_;
  bool power_ = false;
  double start_ = 0.0;
  Point c_[4] = {};
};

// Curvature |C' x C''| / |C'|^3, in 1/length. Zero where C' vanishes.
double curvature(const Curve& curve, double u);
double curvature(const Curve& curve, int span, double u);  // span: find_span(curve, u)
// Torsion (C' x C'') . C''' / |C' x C''|^2, in 1/length. Zero where C' x C'' vanishes.
double torsion(const Curve& curve, double u);
// Arc length of C over [u0, u1] (u0 <= u1), by adaptive Gauss-Legendre quadrature to a
// relative accuracy of about 1e-10.
double arc_length(const Curve& curve, double u0, double u1);

// Arc length of a short piece of C over [u0, u1] by one 5-point Gauss-Legendre rule per
// knot span it crosses, without arc_length's adaptive refinement: for the spacing of sweep
// samples it agrees with arc_length to the snapshots' 0.001 mm over a whole fabric, at a
// fraction of the cost.
double segment_length(const Curve& curve, double u0, double u1);
// segment_length of every step of ascending parameters u: out[i] for [u[i], u[i + 1]]
// (out.size() == u.size() - 1), the same rule, each knot span made ready once.
void segment_lengths(const Curve& curve, std::span<const double> u, std::span<double> out);

enum class Parametrisation {
  chord_length,  // parameter steps proportional to |Q_k - Q_{k-1}| (P&T eq. 9.5)
  centripetal,   // proportional to |Q_k - Q_{k-1}|^(1/2) (P&T eq. 9.6)
};

struct InterpolationOptions {
  Parametrisation parametrisation = Parametrisation::chord_length;
  // End derivatives dC/du at u = 0 and u = 1 (P&T section 9.2.2). Note the unit: per
  // unit of the normalised parameter, so a tangent direction t with the curve's
  // chord length L is asked for as L * t.
  std::optional<Point> start_derivative;
  std::optional<Point> end_derivative;
  // Threads the system's rows are filled on (0: every core); the curve is the same for any.
  int threads = 1;
};

struct Interpolant {
  Curve curve;
  // The parameter of each data point: curve(parameters[k]) == data[k].
  std::vector<double> parameters;
};

// A non-rational curve of degree min(3, data.size() - 1) through every data point,
// parameters in [0, 1] by the chosen parametrisation, knots by averaging (P&T eq. 9.8;
// eq. 9.22 with end derivatives), control points from the banded linear system (A9.1).
// Needs at least two data points and no two consecutive ones equal; throws
// std::invalid_argument otherwise.
Interpolant interpolate(std::span<const Point> data, const InterpolationOptions& options = {});

}  // namespace knitc::nurbs
