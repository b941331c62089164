#pragma once
// Shape functions of the background grid, each a small type with the 1D weight
// and its derivative; the D-dimensional function is their tensor product. The
// solver is instantiated per shape type, chosen by name once per run, so there
// is no virtual call per particle-node pair.
#include <array>
#include <cmath>
#include <string_view>

namespace talus::mpm {

enum class ShapeKind { Linear, Gimp, CubicBSpline };

// All 1D functions take r = (x_p - x_node)/h and return N(r) and dN/dr; `l` is
// the particle half-width over h (used by GIMP only).

// Classic hat function: C0, cell-crossing noise.
struct LinearShape {
  static constexpr int support = 2;  // nodes per axis
  static constexpr std::string_view name = "linear";
  // Index of the first node of the stencil for a position in cell units.
  static int first(double xn) { return static_cast<int>(std::floor(xn)); }
  static void eval(double r, double /*l*/, double& w, double& dw) {
    const double a = std::abs(r);
    w = a < 1.0 ? 1.0 - a : 0.0;
    dw = a < 1.0 ? (r >= 0.0 ? -1.0 : 1.0) : 0.0;
  }
};

// Uniform GIMP (Bardenhagen & Kober 2004): the hat function convolved with a
// particle of half-width l h that keeps its initial size. Valid for l <= 1/2.
struct GimpShape {
  static constexpr int support = 3;
  static constexpr std::string_view name = "gimp";
  static int first(double xn) { return static_cast<int>(std::floor(xn - 0.5)); }
  static void eval(double r, double l, double& w, double& dw) {
    const double a = std::abs(r), sign = r >= 0.0 ? 1.0 : -1.0;
    if (a < l) {
      w = 1.0 - (r * r + l * l) / (2.0 * l);
      dw = -r / l;
    } else if (a < 1.0 - l) {
      w = 1.0 - a;
      dw = -sign;
    } else if (a < 1.0 + l) {
      const double b = 1.0 + l - a;
      w = b * b / (4.0 * l);
      dw = -sign * b / (2.0 * l);
    } else {
      w = dw = 0.0;
    }
  }
};

// Cubic B-spline of mpm.md / OpenLISEM: C2, support of two cells each side.
struct CubicBSplineShape {
  static constexpr int support = 4;
  static constexpr std::string_view name = "cubic_bspline";
  static int first(double xn) { return static_cast<int>(std::floor(xn)) - 1; }
  static void eval(double r, double /*l*/, double& w, double& dw) {
    const double a = std::abs(r);
    if (a < 1.0) {
      w = 0.5 * a * a * a - r * r + 2.0 / 3.0;
      dw = 1.5 * r * a - 2.0 * r;
    } else if (a < 2.0) {
      const double sign = r >= 0.0 ? 1.0 : -1.0;
      w = -a * a * a / 6.0 + r * r - 2.0 * a + 4.0 / 3.0;
      dw = -0.5 * r * a + 2.0 * r - 2.0 * sign;
    } else {
      w = dw = 0.0;
    }
  }
};

// Calls f(ShapeType{}) for the kind: the one switch outside the hot loops.
template <class F>
decltype(auto) with_shape(ShapeKind kind, F&& f) {
  switch (kind) {
    case ShapeKind::Linear:
      return f(LinearShape{});
    case ShapeKind::Gimp:
      return f(GimpShape{});
    case ShapeKind::CubicBSpline:
      break;
  }
  return f(CubicBSplineShape{});
}

}  // namespace talus::mpm
