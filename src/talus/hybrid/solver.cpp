#include "talus/hybrid/solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "talus/core/error.hpp"

namespace talus::hybrid {

namespace {

// The cell holding (x, y), clamped to the grid.
std::size_t cell_at(const runout::GridShape& g, double x, double y) {
  const auto i =
      static_cast<std::size_t>(std::clamp(x / g.dx, 0.0, static_cast<double>(g.nx) - 0.5));
  const auto j =
      static_cast<std::size_t>(std::clamp(y / g.dy, 0.0, static_cast<double>(g.ny) - 0.5));
  return g.index(i, j);
}

// Interpolates a per-cell field bilinearly between cell centres (clamped at
// the outer half cells); next to a cell outside the domain (whose slope is
// not the ground's) it takes the value of the cell holding the point.
double bilinear(const runout::Terrain& terrain, const std::vector<double>& f, double x, double y) {
  const runout::GridShape& g = terrain.shape();
  const double fx = std::clamp(x / g.dx - 0.5, 0.0, static_cast<double>(g.nx - 1));
  const double fy = std::clamp(y / g.dy - 0.5, 0.0, static_cast<double>(g.ny - 1));
  const std::size_t i = std::min(static_cast<std::size_t>(fx), g.nx > 1 ? g.nx - 2 : 0);
  const std::size_t j = std::min(static_cast<std::size_t>(fy), g.ny > 1 ? g.ny - 2 : 0);
  const double tx = g.nx > 1 ? fx - static_cast<double>(i) : 0.0;
  const double ty = g.ny > 1 ? fy - static_cast<double>(j) : 0.0;
  const std::size_t i1 = g.nx > 1 ? i + 1 : i, j1 = g.ny > 1 ? j + 1 : j;
  const auto& in = terrain.inside();
  const std::size_t c00 = g.index(i, j), c10 = g.index(i1, j), c01 = g.index(i, j1),
                    c11 = g.index(i1, j1);
  if (!in[c00] || !in[c10] || !in[c01] || !in[c11]) return f[cell_at(g, x, y)];
  return (1 - ty) * ((1 - tx) * f[c00] + tx * f[c10]) + ty * ((1 - tx) * f[c01] + tx * f[c11]);
}

// The Drucker-Prager model with its critical volume strain for this kernel
// (the crack-band form scales with the smoothing length as MPM's with the cell).
mpm::DruckerPrager make_material(mpm::MaterialParams m, double smoothing_length) {
  if (smoothing_length > 0.0)
    m.critical_volume_strain = mpm::critical_volume_strain(m, smoothing_length);
  return mpm::DruckerPrager::make(m);
}

void require(bool ok, const std::string& what) {
  if (!ok) throw InputError("hybrid: " + what);
}

}  // namespace

HybridSolver::HybridSolver(runout::Terrain terrain, HybridParams params, Particles particles,
                           double particle_spacing)
    : terrain_(std::move(terrain)),
      params_(std::move(params)),
      p_(std::move(particles)),
      kernel_(params_.smoothing_length > 0.0 ? params_.smoothing_length : 1.0),
      material_(make_material(params_.material, params_.smoothing_length)),
      nonlocal_(params_.material.nonlocal_length) {
  const HybridParams& q = params_;
  require(q.smoothing_length > 0.0 && std::isfinite(q.smoothing_length),
          "smoothing_length must be > 0");
  require(
      q.material.model == mpm::DruckerPrager::name,
      fmt::format("the structured material must be drucker_prager, not '{}'", q.material.model));
  require(q.material.density > 0.0, "the material's density must be > 0");
  if (const auto problem = mpm::DruckerPrager::check(q.material))
    throw InputError(fmt::format("hybrid: material key '{}': {}", problem.key, problem.message));
  require(q.tan_basal_friction >= 0.0, "the basal friction must be >= 0");
  require(q.viscosity_alpha >= 0.0 && q.viscosity_beta >= 0.0,
          "the artificial viscosity's alpha and beta must be >= 0");
  require(q.artificial_stress >= 0.0 && q.artificial_stress_exponent > 0,
          "the artificial stress needs eps >= 0 and an exponent > 0");
  require(q.courant > 0.0 && q.courant <= 1.0, "courant must be in (0, 1]");
  require(particle_spacing > 0.0, "the particle spacing must be > 0");
  const auto& g = terrain_.shape();
  const double width = static_cast<double>(g.nx) * g.dx, height = static_cast<double>(g.ny) * g.dy;
  // The messages are formatted only for a particle that fails.
  for (std::size_t k = 0; k < p_.size(); ++k) {
    const double x = p_.x[k], y = p_.y[k];
    if (!(x >= 0.0 && x <= width && y >= 0.0 && y <= height))
      require(false, fmt::format("particle {} at ({}, {}) is outside the terrain", k, x, y));
    if (!terrain_.inside()[cell_at(g, x, y)])
      require(false, fmt::format("particle {} at ({}, {}) is in a cell outside the domain (an "
                                 "obstacle)",
                                 k, x, y));
    if (!(p_.mass[k] > 0.0)) require(false, fmt::format("particle {} has no mass", k));
  }
  rho_c_ = q.material.density;
  c0_ = q.material.cohesion;
  const double s = std::sin(q.material.friction_angle);
  k_active_ = (1.0 - s) / (1.0 + s);  // Rankine (eq. 42)
  sqrt_k_active_ = std::sqrt(k_active_);
  w_d0_ = kernel_.value(particle_spacing);
  sound_speed_ = material_.wave_speed();
  for (auto& st : p_.state) st.cohesion = c0_;
  const std::size_t n = p_.size();
  for (auto* a : {&sxx_, &sxy_, &syy_, &rxx_, &rxy_, &ryy_, &ax_, &ay_, &loss_, &averaged_})
    a->assign(n, 0.0);
  gradient_.assign(4 * n, 0.0);
}

HybridSolver::Bed HybridSolver::bed_at(double x, double y, double u, double v) const {
  const double bx = bilinear(terrain_, terrain_.slope_x(), x, y);
  const double by = bilinear(terrain_, terrain_.slope_y(), x, y);
  const double cos2 = 1.0 / (1.0 + bx * bx + by * by);
  // A point held on the surface z = b(x, y) and moving with horizontal
  // velocity u has the bed's reaction per unit mass (g + u^T Hess(b) u)
  // cos^2 along the normal (the centripetal part as fv2d's bed load): its
  // horizontal pull is that times -grad(b), and it is the friction's load.
  double load = params_.gravity;
  if (params_.curvature && (u != 0.0 || v != 0.0)) {
    const double bxx = bilinear(terrain_, terrain_.curvature_xx(), x, y);
    const double bxy = bilinear(terrain_, terrain_.curvature_xy(), x, y);
    const double byy = bilinear(terrain_, terrain_.curvature_yy(), x, y);
    load = std::max(0.0, load + bxx * u * u + 2.0 * bxy * u * v + byy * v * v);
  }
  const double gn = load * cos2;
  return {-gn * bx, -gn * by, gn, params_.gravity * cos2};
}

double HybridSolver::lateral_force(double depth, double cohesion, double normal_gravity) const {
  const double gamma = rho_c_ * normal_gravity;
  if (!params_.earth_pressure || depth <= 0.0 || gamma <= 0.0) return 0.0;
  // The active pressure K gamma z - 2 c sqrt(K) is zero down to z0 (Bell's
  // tension zone, which carries nothing), then grows linearly.
  const double z0 = 2.0 * cohesion * sqrt_k_active_ / (k_active_ * gamma);
  if (z0 >= depth) return 0.0;
  const double d = depth - z0;
  return 0.5 * k_active_ * gamma * d * d;
}

double HybridSolver::stable_time_step() const {
  double vmax = 0.0;
  for (std::size_t k = 0; k < p_.size(); ++k) vmax = std::max(vmax, std::hypot(p_.u[k], p_.v[k]));
  return params_.courant * params_.smoothing_length / (sound_speed_ + vmax);
}

void HybridSolver::neighbours() {
  // Two passes (count, then fill) so that every particle's list is in the
  // same order for any number of threads.
  grid_.build(p_.x, p_.y, kernel_.support());
  const auto n = static_cast<long>(p_.size());
  const double r2max = kernel_.support() * kernel_.support();
  list_start_.assign(p_.size() + 1, 0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double xi = p_.x[i], yi = p_.y[i];
    std::size_t count = 0;
    grid_.for_near(xi, yi, [&](int j) {
      const double dx = xi - p_.x[j], dy = yi - p_.y[j];
      if (j != i && dx * dx + dy * dy < r2max) ++count;
    });
    list_start_[i + 1] = count;
  }
  for (std::size_t i = 0; i < p_.size(); ++i) list_start_[i + 1] += list_start_[i];
  const std::size_t pairs = list_start_.back();
  pair_j_.resize(pairs);
  pair_dx_.resize(pairs);
  pair_dy_.resize(pairs);
  pair_w_.resize(pairs);
  pair_dw_.resize(pairs);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double xi = p_.x[i], yi = p_.y[i];
    std::size_t k = list_start_[i];
    grid_.for_near(xi, yi, [&](int j) {
      const double dx = xi - p_.x[j], dy = yi - p_.y[j];
      const double r2 = dx * dx + dy * dy;
      if (j == i || r2 >= r2max) return;
      const double r = std::sqrt(r2);
      pair_j_[k] = j;
      pair_dx_[k] = dx;
      pair_dy_[k] = dy;
      pair_w_[k] = kernel_.value(r);
      pair_dw_[k] = kernel_.derivative_over_r(r);
      ++k;
    });
  }
}

void HybridSolver::densities() {
  const auto n = static_cast<long>(p_.size());
  const double self = kernel_.value(0.0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    double sum = p_.mass[i] * self;
    for (std::size_t k = list_start_[i]; k < list_start_[i + 1]; ++k)
      sum += p_.mass[pair_j_[k]] * pair_w_[k];
    p_.areal[i] = sum;
    p_.depth[i] = sum / rho_c_;
  }
}

void HybridSolver::stresses(double dt) {
  const auto n = static_cast<long>(p_.size());
  const double eps = params_.artificial_stress;
  // The velocity gradient (the form that pairs with the momentum equation's
  // sum: the work of the stress is then exactly the forces' work).
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double ui = p_.u[i], vi = p_.v[i];
    double l00 = 0.0, l01 = 0.0, l10 = 0.0, l11 = 0.0;
    for (std::size_t k = list_start_[i]; k < list_start_[i + 1]; ++k) {
      const int j = pair_j_[k];
      const double dx = pair_dx_[k], dy = pair_dy_[k];
      const double w = p_.mass[j] * pair_dw_[k];
      const double du = p_.u[j] - ui, dv = p_.v[j] - vi;
      l00 += w * du * dx;
      l01 += w * du * dy;
      l10 += w * dv * dx;
      l11 += w * dv * dy;
    }
    const double inv = 1.0 / p_.areal[i];
    gradient_[4 * i] = l00 * inv;
    gradient_[4 * i + 1] = l01 * inv;
    gradient_[4 * i + 2] = l10 * inv;
    gradient_[4 * i + 3] = l11 * inv;
    loss_[i] = std::max(0.0, (l00 + l11) * inv) * dt;
  }
  if (nonlocal_ > 0.0) average_dilation();
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double xi = p_.x[i], yi = p_.y[i];
    mpm::Mat3 l = mpm::Mat3::Zero();
    l(0, 0) = gradient_[4 * i];
    l(0, 1) = gradient_[4 * i + 1];
    l(1, 0) = gradient_[4 * i + 2];
    l(1, 1) = gradient_[4 * i + 3];
    mpm::MaterialState& st = p_.state[i];
    material_.update(st, l, dt, nonlocal_ > 0.0 ? averaged_[i] : loss_[i]);
    const Bed bed = bed_at(xi, yi, 0.0, 0.0);
    const double h = p_.depth[i];
    const double pressure = lateral_force(h, st.cohesion, bed.weight);
    const double inv_rho2 = 1.0 / (p_.areal[i] * p_.areal[i]);
    const double sxx = (h * st.stress(0, 0) - pressure) * inv_rho2;
    const double sxy = h * st.stress(0, 1) * inv_rho2;
    const double syy = (h * st.stress(1, 1) - pressure) * inv_rho2;
    sxx_[i] = sxx;
    sxy_[i] = sxy;
    syy_[i] = syy;
    // Artificial stress: in S's principal axes, -eps times each tensile
    // principal value (Gray et al. 2001), rotated back.
    double rxx = 0.0, rxy = 0.0, ryy = 0.0;
    if (eps > 0.0) {
      const double mean = 0.5 * (sxx + syy), half = 0.5 * (sxx - syy);
      const double radius = std::hypot(half, sxy);
      const double s1 = mean + radius, s2 = mean - radius;
      const double r1 = s1 > 0.0 ? -eps * s1 : 0.0, r2 = s2 > 0.0 ? -eps * s2 : 0.0;
      // Unit vector of s1: angle theta with tan(2 theta) = 2 sxy / (sxx - syy).
      const double theta = 0.5 * std::atan2(sxy, half);
      const double c = std::cos(theta), s = std::sin(theta);
      rxx = r1 * c * c + r2 * s * s;
      ryy = r1 * s * s + r2 * c * c;
      rxy = (r1 - r2) * c * s;
    }
    rxx_[i] = rxx;
    rxy_[i] = rxy;
    ryy_[i] = ryy;
  }
}

void HybridSolver::average_dilation() {
  // The dilation that breaks bonds, averaged as the plan-view MPM averages
  // it (mpm/nonlocal.hpp): mass-weighted tent functions onto a lattice of
  // spacing L = nonlocal_length and back, a smooth kernel of half-width 2 L
  // fixed in space, so the crack's width does not follow the particles'.
  // Serial accumulation in particle order: the same bits on any team.
  const std::size_t n = p_.size();
  if (n == 0) return;
  const double ell = nonlocal_;
  const auto [xmin, xmax] = std::minmax_element(p_.x.begin(), p_.x.end());
  const auto [ymin, ymax] = std::minmax_element(p_.y.begin(), p_.y.end());
  const double x0 = *xmin - ell, y0 = *ymin - ell;
  const auto nx = static_cast<std::size_t>((*xmax - x0) / ell) + 2;
  const auto ny = static_cast<std::size_t>((*ymax - y0) / ell) + 2;
  lattice_.assign(2 * nx * ny, 0.0);
  auto corners = [&](std::size_t k, std::size_t& c, double& fx, double& fy) {
    const double sx = (p_.x[k] - x0) / ell, sy = (p_.y[k] - y0) / ell;
    const auto i = std::min(static_cast<std::size_t>(sx), nx - 2);
    const auto j = std::min(static_cast<std::size_t>(sy), ny - 2);
    fx = sx - static_cast<double>(i);
    fy = sy - static_cast<double>(j);
    c = j * nx + i;
  };
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t c;
    double fx, fy;
    corners(k, c, fx, fy);
    const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    const std::size_t node[4] = {c, c + 1, c + nx, c + nx + 1};
    for (int q = 0; q < 4; ++q) {
      lattice_[2 * node[q]] += w[q] * p_.mass[k] * loss_[k];
      lattice_[2 * node[q] + 1] += w[q] * p_.mass[k];
    }
  }
  const auto count = static_cast<long>(n);
#pragma omp parallel for schedule(static)
  for (long k = 0; k < count; ++k) {
    std::size_t c;
    double fx, fy;
    corners(static_cast<std::size_t>(k), c, fx, fy);
    const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    const std::size_t node[4] = {c, c + 1, c + nx, c + nx + 1};
    double sum = 0.0, weight = 0.0;
    for (int q = 0; q < 4; ++q) {
      const double m = lattice_[2 * node[q] + 1];
      if (m > 0.0) {
        sum += w[q] * lattice_[2 * node[q]] / m;
        weight += w[q];
      }
    }
    averaged_[k] = weight > 0.0 ? sum / weight : loss_[k];
  }
}

void HybridSolver::accelerations() {
  const auto n = static_cast<long>(p_.size());
  const double l = params_.smoothing_length;
  const int exponent = params_.artificial_stress_exponent;
  const double alpha = params_.viscosity_alpha, beta = params_.viscosity_beta;
  const bool artificial = params_.artificial_stress > 0.0;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double ui = p_.u[i], vi = p_.v[i];
    double axi = 0.0, ayi = 0.0;
    for (std::size_t k = list_start_[i]; k < list_start_[i + 1]; ++k) {
      const int j = pair_j_[k];
      const double dx = pair_dx_[k], dy = pair_dy_[k];
      double txx = sxx_[i] + sxx_[j], txy = sxy_[i] + sxy_[j], tyy = syy_[i] + syy_[j];
      if (artificial) {
        const double ratio = pair_w_[k] / w_d0_;
        double f = ratio;
        for (int e = 1; e < exponent; ++e) f *= ratio;
        txx += f * (rxx_[i] + rxx_[j]);
        txy += f * (rxy_[i] + rxy_[j]);
        tyy += f * (ryy_[i] + ryy_[j]);
      }
      const double approach = (ui - p_.u[j]) * dx + (vi - p_.v[j]) * dy;
      if (approach < 0.0) {
        const double mu = l * approach / (dx * dx + dy * dy + 0.01 * l * l);
        const double pi =
            (-alpha * sound_speed_ * mu + beta * mu * mu) / (0.5 * (p_.areal[i] + p_.areal[j]));
        txx -= pi;
        tyy -= pi;
      }
      const double w = p_.mass[j] * pair_dw_[k];
      axi += w * (txx * dx + txy * dy);
      ayi += w * (txy * dx + tyy * dy);
    }
    ax_[i] = axi;
    ay_[i] = ayi;
  }
}

void HybridSolver::integrate(double dt) {
  const auto n = static_cast<long>(p_.size());
  const auto& g = terrain_.shape();
  const double width = static_cast<double>(g.nx) * g.dx, height = static_cast<double>(g.ny) * g.dy;
  const double mu = params_.tan_basal_friction, wall_mu = params_.wall_friction;
  const bool has_walls = terrain_.has_outside();
  const auto& inside = terrain_.inside();
  auto reduce = [](double w, double by) {
    return std::abs(w) <= by ? 0.0 : w - std::copysign(by, w);
  };
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const Bed bed = bed_at(p_.x[i], p_.y[i], p_.u[i], p_.v[i]);
    double u = p_.u[i] + dt * (ax_[i] + bed.gx), v = p_.v[i] + dt * (ay_[i] + bed.gy);
    // Basal Coulomb friction as an impulse: it stops the particle, never
    // reverses it.
    const double speed = std::hypot(u, v), stop = dt * mu * bed.load;
    if (speed <= stop) {
      u = v = 0.0;
    } else if (stop > 0.0) {
      const double scale = 1.0 - stop / speed;
      u *= scale;
      v *= scale;
    }
    double x = p_.x[i] + dt * u, y = p_.y[i] + dt * v;
    // Walls at the terrain's edges: the normal velocity is removed.
    if (x < 0.0 || x > width) {
      x = std::clamp(x, 0.0, width);
      u = 0.0;
    }
    if (y < 0.0 || y > height) {
      y = std::clamp(y, 0.0, height);
      v = 0.0;
    }
    // Cells outside the domain (no-data: obstacles) are walls along the
    // grid's axes: a move into one is undone along that axis, its normal
    // velocity removed and the tangential one reduced by wall_friction times
    // that normal change (Coulomb), never reversed.
    if (has_walls) {
      const double x0 = p_.x[i], y0 = p_.y[i];
      auto blocked = [&](double px, double py) { return !inside[cell_at(g, px, py)]; };
      if (blocked(x, y0)) {
        v = reduce(v, wall_mu * std::abs(u));
        u = 0.0;
        x = x0;
      }
      if (blocked(x, y)) {
        u = reduce(u, wall_mu * std::abs(v));
        v = 0.0;
        y = y0;
      }
    }
    p_.u[i] = u;
    p_.v[i] = v;
    p_.x[i] = x;
    p_.y[i] = y;
  }
  for (long i = 0; i < n; ++i)
    if (!std::isfinite(p_.u[i]) || !std::isfinite(p_.v[i]))
      throw RunError(fmt::format(
          "hybrid: particle {}'s velocity is not finite at t = {:.6g} s (near x = {:.4g}, y = "
          "{:.4g}); the step {:.3g} s may be too long for the material's stiffness",
          i, time_, p_.x[i], p_.y[i], dt));
}

void HybridSolver::step(double dt) {
  neighbours();
  densities();
  stresses(dt);
  accelerations();
  integrate(dt);
  time_ += dt;
}

HybridTotals HybridSolver::totals() const {
  HybridTotals t;
  for (std::size_t k = 0; k < p_.size(); ++k) {
    const double m = p_.mass[k], s2 = p_.u[k] * p_.u[k] + p_.v[k] * p_.v[k];
    t.mass += m;
    t.momentum_x += m * p_.u[k];
    t.momentum_y += m * p_.v[k];
    t.kinetic_energy += 0.5 * m * s2;
    t.max_speed = std::max(t.max_speed, std::sqrt(s2));
  }
  return t;
}

double HybridSolver::strength_fraction(std::size_t k) const {
  return c0_ > 0.0 ? p_.state[k].cohesion / c0_ : 1.0;
}

}  // namespace talus::hybrid
