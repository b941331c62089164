#pragma once
// Building blocks of the DEM verification tests (spec/dem.md, "Verification
// cases"): scenarios built in code, particle lookup by id, and the measurement
// of one impact step by step. The same helpers serve 2D (disks, "up" is +y,
// walls are segments) and 3D (spheres, "up" is +z, walls are planes).
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/params.hpp"
#ifdef TALUS_TEST_GPU_BACKEND
#include "dem_gpu/test_backend.hpp"
#endif

namespace talus::dem::verification {

// A case ready to run: on the CPU stepper, or, where these tests are compiled
// into test_dem_gpu (TALUS_TEST_GPU_BACKEND), on the GPU backend the test run
// names (tests/dem_gpu/test_backend.hpp), with the same tolerances.
template <int D>
std::unique_ptr<DemRun<D>> build(const DemScenario& sc) {
  auto run = build_dem<D>(sc, {});
#ifdef TALUS_TEST_GPU_BACKEND
  run->stepper = test::backend_stepper<D>(run->system);
#endif
  return run;
}

// The axis gravity acts along: y for disks, z for spheres.
template <int D>
constexpr int kUp = D - 1;

template <int D>
Vec3 up() {
  return D == 2 ? Vec3::UnitY() : Vec3::UnitZ();
}

// gtest typed-test parameters.
using Dim2 = std::integral_constant<int, 2>;
using Dim3 = std::integral_constant<int, 3>;

inline MaterialParams hertz_material(const std::string& name, double density, double youngs,
                                     double poisson, double restitution, double friction) {
  MaterialParams m;
  m.name = name;
  m.density = density;
  m.youngs_modulus = youngs;
  m.poisson_ratio = poisson;
  m.restitution = restitution;
  m.friction = friction;
  return m;
}

inline MaterialParams linear_material(const std::string& name, double density, double kn, double ks,
                                      double beta, double friction) {
  MaterialParams m;
  m.name = name;
  m.density = density;
  m.normal_stiffness = kn;
  m.shear_stiffness = ks;
  m.damping_ratio = beta;
  m.friction = friction;
  return m;
}

// A wall material that adds no compliance (E = 0 and k = 0 mean rigid,
// contact/pair_coefficients.hpp), no damping (restitution 1 and beta 0 lose
// against the particle's under the min / max rules) and, with the default
// friction rule "max", the particle's friction unless `friction` is larger.
inline MaterialParams rigid_material(const std::string& name, double friction = 0.0) {
  MaterialParams m;
  m.name = name;
  m.density = 1.0;
  m.youngs_modulus = 0.0;
  m.restitution = 1.0;
  m.friction = friction;
  return m;
}

inline DemScenario scenario(int dimension, std::string_view model, double time_step,
                            const Vec3& gravity) {
  DemScenario sc;
  sc.name = "verification";
  sc.run.dimension = dimension;
  sc.run.time_step = time_step;
  sc.run.gravity = gravity;
  sc.contact.model = model;
  return sc;
}

inline ParticleSpec ball(const Vec3& x, const Vec3& v, double r, const std::string& material,
                         const Vec3& w = Vec3::Zero()) {
  ParticleSpec p;
  p.position = x;
  p.velocity = v;
  p.angular_velocity = w;
  p.radius = r;
  p.material = material;
  return p;
}

// Particles given one by one; ids follow the order of `balls` (0, 1, ...).
inline void add_balls(DemScenario& sc, const std::vector<ParticleSpec>& balls) {
  ParticleSourceParams src;
  src.kind = SourceKind::List;
  src.particles = balls;
  sc.sources.push_back(src);
}

// A flat wall through `point` facing `normal`: a plane in 3D, a long segment
// (half length `half_length`) in 2D, where `normal` must lie in the x-y plane.
template <int D>
WallParams flat_wall(const std::string& name, const std::string& material, const Vec3& point,
                     const Vec3& normal, double half_length = 1.0) {
  WallParams w;
  w.name = name;
  w.material = material;
  if constexpr (D == 3) {
    w.kind = WallKind::Plane;
    w.point = point;
    w.normal = normal.normalized();
  } else {
    w.kind = WallKind::Segment;
    const Vec3 along(-normal.y(), normal.x(), 0.0);
    w.a = point - half_length * along.normalized();
    w.b = point + half_length * along.normalized();
  }
  return w;
}

// The horizontal floor at height h along the up axis.
template <int D>
WallParams floor_wall(const std::string& material, double h = 0.0) {
  return flat_wall<D>("floor", material, h * up<D>(), up<D>());
}

// A closed box [lo, hi] (x-y in 2D): "floor" first, then the sides and, when
// `lid`, the "lid" at the top. Side walls and lid use `side_material`.
template <int D>
void add_box(DemScenario& sc, const Vec3& lo, const Vec3& hi, const std::string& floor_material,
             const std::string& side_material, bool lid) {
  const Vec3 mid = 0.5 * (lo + hi);
  const double reach = (hi - lo).norm();
  Vec3 floor_point = mid, lid_point = mid;
  floor_point[kUp<D>] = lo[kUp<D>];
  lid_point[kUp<D>] = hi[kUp<D>];
  sc.walls.push_back(flat_wall<D>("floor", floor_material, floor_point, up<D>(), reach));
  for (int d = 0; d < D - 1; ++d) {
    Vec3 a = mid, b = mid;
    a[d] = lo[d];
    b[d] = hi[d];
    const Vec3 e = Vec3::Unit(d);
    sc.walls.push_back(flat_wall<D>("side_lo" + std::to_string(d), side_material, a, e, reach));
    sc.walls.push_back(flat_wall<D>("side_hi" + std::to_string(d), side_material, b, -e, reach));
  }
  if (lid) sc.walls.push_back(flat_wall<D>("lid", side_material, lid_point, -up<D>(), reach));
}

// Particles are re-sorted at neighbour-list rebuilds: find them by id.
template <int D>
std::size_t index_of(const Particles<D>& p, int64_t id) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == id) return i;
  throw std::runtime_error("particle " + std::to_string(id) + " not found");
}

// Exact contact duration of a Hertz impact in units of delta_max / v:
// t_c = 2 (delta_max / v) * int_0^1 (1 - x^(5/2))^(-1/2) dx = (4/5) B(2/5, 1/2) * delta_max / v
// (energy integral of the undamped Hertz oscillator; = 2.9432). Multiplied by
// (15/16)^(2/5) it gives the 2.87 of the spec's rounded formula.
inline double hertz_duration_factor() {
  return 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
}

// Peak overlap, peak contact force and duration of one impact, with the
// velocity and spin of one particle before and after.
template <int D>
struct Impact {
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;
  double max_overlap = 0.0, max_force = 0.0;
  double t_start = -1.0, t_end = -1.0;  // overlap zero crossings, interpolated between steps
  Vec v_in = Vec::Zero(), v_out = Vec::Zero();
  Rot w_out = Space<D>::rot_zero();
  bool finished = false;
  double duration() const { return t_end - t_start; }
};

// Primes a fresh run and steps it until the contact seen by `overlap` (a
// function of the particles, positive while touching) has begun and ended, or
// max_steps passed. The force is the total contact force on particle `id`
// (walls and one partner only, so it is the force of this contact).
template <int D, class OverlapFn>
Impact<D> measure_impact(DemRun<D>& run, int64_t id, OverlapFn overlap, int64_t max_steps) {
  Impact<D> out;
  auto& s = run.system;
  const auto& p = s.particles;
  run.stepper->prime();
  out.v_in = p.v[index_of(p, id)];
  double prev = overlap(p), prev_t = s.time;
  for (int64_t k = 0; k < max_steps; ++k) {
    run.stepper->advance(1);
    const double ov = overlap(p);
    const std::size_t i = index_of(p, id);
    if (ov > 0.0) {
      if (prev <= 0.0) out.t_start = prev_t + (s.time - prev_t) * (-prev) / (ov - prev);
      out.max_overlap = std::max(out.max_overlap, ov);
      out.max_force = std::max(out.max_force, p.f[i].norm());
    } else if (prev > 0.0 && out.t_start >= 0.0) {
      out.t_end = prev_t + (s.time - prev_t) * prev / (prev - ov);
      out.v_out = p.v[i];
      out.w_out = p.w[i];
      out.finished = true;
      return out;
    }
    prev = ov;
    prev_t = s.time;
  }
  return out;
}

// Overlap of particles a and b.
template <int D>
auto pair_overlap(int64_t a, int64_t b) {
  return [a, b](const Particles<D>& p) {
    const std::size_t i = index_of(p, a), j = index_of(p, b);
    return p.r[i] + p.r[j] - (p.x[i] - p.x[j]).norm();
  };
}

// Overlap of particle a with the floor at height 0.
template <int D>
auto floor_overlap(int64_t a) {
  return [a](const Particles<D>& p) {
    const std::size_t i = index_of(p, a);
    return p.r[i] - p.x[i][kUp<D>];
  };
}

}  // namespace talus::dem::verification
