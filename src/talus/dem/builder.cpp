#include "talus/dem/builder.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "talus/core/error.hpp"
#include "talus/core/memory_limit.hpp"
#include "talus/dem/membrane/beam_rig.hpp"
#include "talus/dem/membrane/from_spec.hpp"
#include "talus/dem/membrane/gripper.hpp"
#include "talus/dem/packing.hpp"

namespace talus::dem {

double peer_jitter_hash(int i, int j, int k, int c) {
  const double u = 43758.5453 * std::sin(12.9898 * i + 78.233 * j + 37.719 * k + 4.1414 * c);
  return u - std::floor(u);
}

namespace {

struct Placed {
  Vec3 x, v, w;
  double r;
  int material;
};

int material_of(const DemScenario& sc, const std::string& name, const std::string& where) {
  for (std::size_t k = 0; k < sc.materials.size(); ++k)
    if (sc.materials[k].name == name) return static_cast<int>(k);
  throw InputError(where + ": unknown material '" + name + "'");
}

void lattice(const ParticleSourceParams& s, int dim, int mat, std::vector<Placed>& out) {
  const double a = s.spacing;
  int n[3] = {1, 1, 1};
  for (int d = 0; d < dim; ++d)
    n[d] = static_cast<int>(std::floor((s.box_max[d] - s.box_min[d]) / a + 1e-9));
  const double amp = 0.4 * (a - 2.0 * s.radius);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        Vec3 x = s.box_min + Vec3((i + 0.5) * a, (j + 0.5) * a, dim == 3 ? (k + 0.5) * a : 0.0);
        if (s.jitter == "peer") {
          x.x() += amp * (2.0 * peer_jitter_hash(i, j, k, 0) - 1.0);
          x.y() += amp * (2.0 * peer_jitter_hash(i, j, k, 1) - 1.0);
        }
        out.push_back({x, Vec3::Zero(), Vec3::Zero(), s.radius, mat});
      }
}

void from_file(const ParticleSourceParams& s, int mat, std::vector<Placed>& out) {
  std::ifstream in(s.file);
  if (!in) throw InputError(s.file + ": cannot open particle file");
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0])))
      continue;
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream ls(line);
    double x, y, z, r;
    if (!(ls >> x >> y >> z >> r) || !(r > 0.0))
      throw InputError(s.file + ":" + std::to_string(lineno) +
                       ": expected 'x, y, z, radius' with a positive radius");
    out.push_back({Vec3(x, y, z), Vec3::Zero(), Vec3::Zero(), r, mat});
  }
}

Region region_of(const ParticleSourceParams& s, int dim) {
  Region reg;
  reg.dimension = dim;
  reg.polygon = s.polygon;
  reg.box_min = s.box_min;
  reg.box_max = s.box_max;
  reg.cylinder_radius = s.cylinder_radius;
  reg.shell_inner_radius = s.shell_inner_radius;
  reg.shell_outer_radius = s.shell_outer_radius;
  reg.edge_radius = s.edge_radius;
  return reg;
}

// Particles a source will place, known before placing them: a lattice's
// sites, a packing's count or its solid volume over the mean particle's.
double expected_count(const ParticleSourceParams& s, int dim) {
  switch (s.kind) {
    case SourceKind::List:
      return static_cast<double>(s.particles.size());
    case SourceKind::Lattice: {
      double n = 1.0;
      for (int d = 0; d < dim; ++d) n *= std::floor((s.box_max[d] - s.box_min[d]) / s.spacing);
      return n;
    }
    case SourceKind::RandomFill:
    case SourceKind::Grow: {
      if (s.count) return *s.count;
      const double r = 0.5 * (s.radius_min + s.radius_max);
      const double ball = dim == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r;
      const double solid = s.kind == SourceKind::Grow ? s.packing_fraction : 1.0 - s.porosity;
      return solid * region_of(s, dim).area_or_volume() / ball;
    }
    case SourceKind::File:
      return 0.0;  // as many as its lines: bounded by the file
  }
  return 0.0;
}

std::vector<Placed> place_particles(const DemScenario& sc, unsigned seed) {
  std::vector<Placed> out;
  const int dim = sc.run.dimension;
  // About 1 KiB per particle: its state, its share of the neighbour list and
  // contact history, the packing's scratch (an order of magnitude, not a bound).
  double expected = 0.0;
  for (std::size_t k = 0; k < sc.sources.size(); ++k) {
    const double n = expected_count(sc.sources[k], dim);
    expected += n;
    check_memory(1024.0 * expected,
                 fmt::format("[[particles]] #{}: about {:.3g} particles{}", k, n,
                             k > 0 ? fmt::format(" ({:.3g} in all)", expected) : ""));
  }
  int index = 0;
  for (const auto& s : sc.sources) {
    const std::string where = "[[particles]] #" + std::to_string(index++);
    const int mat = s.kind == SourceKind::List ? -1 : material_of(sc, s.material, where);
    std::vector<PackedParticle> packed;
    switch (s.kind) {
      case SourceKind::List:
        for (const auto& q : s.particles)
          out.push_back({q.position, q.velocity, q.angular_velocity, q.radius,
                         material_of(sc, q.material, where)});
        break;
      case SourceKind::Lattice:
        lattice(s, dim, mat, out);
        break;
      case SourceKind::File:
        from_file(s, mat, out);
        break;
      case SourceKind::RandomFill:
      case SourceKind::Grow:
        try {
          packed = s.kind == SourceKind::RandomFill
                       ? random_fill(region_of(s, dim), s.radius_min, s.radius_max, s.porosity,
                                     s.count, seed + index)
                       : grow_packing(region_of(s, dim), s.radius_min, s.radius_max,
                                      s.packing_fraction, s.count.value_or(1000), seed + index)
                             .particles;
        } catch (const InputError& e) {
          // Name the source: the packing knows only its region and numbers.
          throw InputError(where + ": " + e.what());
        }
        break;
    }
    if (s.shrink > 0.0) shrink_radii(packed, s.shrink);
    for (const auto& q : packed)
      out.push_back({q.position, Vec3::Zero(), Vec3::Zero(), q.radius, mat});
  }
  return out;
}

template <int D>
void check_inside(const DemScenario& sc, const DemSystem<D>& s) {
  if (!s.has_domain()) return;
  const auto& p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 x = Space<D>::to3(p.x[i]);
    for (int d = 0; d < D; ++d)
      if (x[d] < sc.run.domain_min[d] || x[d] > sc.run.domain_max[d])
        throw InputError(fmt::format(
            "[run] 'domain': particle {} at ({:.6g}, {:.6g}, {:.6g}) lies outside the domain",
            p.id[i], x.x(), x.y(), x.z()));
  }
}

// A wall striking a particle at speed v presses it in by about v t_c, t_c
// being the critical step at that impact speed (exactly v sqrt(m/k) for
// linear springs, 1.4 times that for Hertz at the same speed). Deeper than
// the smallest radius, particles pass through the wall and the contact forces
// are meaningless: the run is refused before it starts.
void check_wall_speed(const geometry::Wall& wall, std::size_t index, double t_c, double r_min) {
  const double v = wall.top_speed();
  if (!(v * t_c > r_min)) return;
  throw InputError(fmt::format(
      "walls.{}.motion: wall '{}' moves at up to {:.4g} m/s; a particle it strikes would be "
      "pressed about {:.3g} m into it, more than the smallest particle radius ({:.3g} m), and "
      "would pass through it. Slow the wall below {:.3g} m/s or stiffen the contacts",
      index, wall.name, v, v * t_c, r_min, r_min / t_c));
}

// Settles packings under gravity with the real contact law until the kinetic
// energy is a small fraction of m g d (Kuen: "until the kinetic energy is negligible").
template <int D>
double settle(DemRun<D>& run, const SettleParams& sp) {
  auto& s = run.system;
  const auto& p = s.particles;
  double m_total = 0.0, d_mean = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    m_total += p.m[i];
    d_mean += 2.0 * p.r[i];
  }
  d_mean /= std::max<std::size_t>(1, p.size());
  const double threshold = sp.ke_ratio * m_total * s.gravity.norm() * d_mean;
  const int64_t chunk = std::max<int64_t>(1, static_cast<int64_t>(1e-3 / s.dt));
  s.settling = true;
  run.stepper->prime();
  while (s.time < sp.max_time) {
    run.stepper->advance(chunk);
    if (kinetic_energy(p) < threshold && s.time > 0.05) break;
  }
  s.settling = false;
  return s.time;
}

}  // namespace

template <int D>
std::unique_ptr<DemRun<D>> build_dem(const DemScenario& sc, const BuildOptions& opt) {
  auto run = std::make_unique<DemRun<D>>();
  auto& s = run->system;
  s.materials = sc.materials;
  s.contact = sc.contact;
  s.gravity = Space<D>::from3(sc.run.gravity);
  s.domain_min = sc.run.domain_min;
  s.domain_max = sc.run.domain_max;
  s.threads = std::max(1, opt.threads);
  for (const auto& w : sc.walls)
    s.walls.push_back(
        geometry::make_wall(w, material_of(sc, w.material, "[[walls]] '" + w.name + "'"), D));

  if constexpr (D == 3) {
    for (const auto& m : sc.membranes) {
      s.membranes.push_back(membrane::make_membrane_body(
          m, material_of(sc, m.material, "[[membranes]] '" + m.name + "'")));
      membrane::attach_rings(s.membranes.back(), m, s.walls);
    }
    if (sc.gripper) membrane::apply_gripper(*sc.gripper, sc, s);
    if (sc.beam) membrane::apply_beam(*sc.beam, sc, s);
  } else if (!sc.membranes.empty()) {
    throw InputError("[[membranes]]: membranes need run.dimension = 3");
  }

  run->stepper = make_stepper<D>(s);
  // A resumed run takes particles, step and skin from its checkpoint.
  if (!opt.place) return run;

  int64_t id = 0;
  double r_max = 0.0, r_min = 1e300, v_max = 0.0;
  for (const Placed& q : place_particles(sc, sc.run.seed)) {
    const MaterialParams& m = sc.materials[q.material];
    if (!(q.r > 0.0)) throw InputError("[[particles]]: radius must be positive");
    s.particles.add(Space<D>::from3(q.x), Space<D>::from3(q.v), Space<D>::rot_from3(q.w), q.r,
                    m.density, q.material, id++);
    r_max = std::max(r_max, q.r);
    r_min = std::min(r_min, q.r);
    v_max = std::max(v_max, q.v.norm() + q.w.norm() * q.r);
  }
  check_inside(sc, s);
  // Kuen's Model 1 (translation only): no particle may start spinning either.
  if (sc.contact.lock_rotation)
    for (auto& w : s.particles.w) w = Space<D>::rot_zero();
  s.skin = sc.run.skin > 0.0 ? sc.run.skin : 0.2 * r_max;
  // Hertz laws need an impact speed: the fastest initial particle, a fall
  // through the domain height or the fastest wall striking a particle, at least 1 m/s.
  const double height = s.has_domain() ? (sc.run.domain_max - sc.run.domain_min).maxCoeff() : 1.0;
  std::size_t fastest = 0;
  for (std::size_t w = 0; w < s.walls.size(); ++w)
    if (s.walls[w].top_speed() > s.walls[fastest].top_speed()) fastest = w;
  const double v_wall = s.walls.empty() ? 0.0 : s.walls[fastest].top_speed();
  s.reference_speed =
      std::max({1.0, 2.0 * v_max, v_wall + v_max, std::sqrt(2.0 * sc.run.gravity.norm() * height)});
  s.critical_time_step = run->stepper->critical_time_step(s.reference_speed);
  if (!s.walls.empty()) check_wall_speed(s.walls[fastest], fastest, s.critical_time_step, r_min);
  if (sc.run.time_step > 0.0) {
    if (sc.run.time_step > s.critical_time_step) {
      // Name the keys behind the critical step: the lightest particle's material.
      const auto& p = s.particles;
      std::string lightest;
      if (p.size() > 0) {
        const auto k = std::min_element(p.m.begin(), p.m.end()) - p.m.begin();
        const auto& m = sc.materials[p.material[k]];
        lightest = fmt::format(
            " (radius {:.4g} m, of [[materials]] '{}': materials.{}.density = "
            "{:.4g} kg/m^3 and its stiffness)",
            p.r[k], m.name, p.material[k], m.density);
      }
      throw InputError(fmt::format(
          "{}: {:.4g} s is above the critical time step {:.4g} s of the stiffest contact and "
          "lightest particle{}; use at most {:.4g} s (or leave time_step out: automatic)",
          sc.run.time_step_source.empty() ? "[run] 'time_step'" : sc.run.time_step_source,
          sc.run.time_step, s.critical_time_step, lightest,
          sc.run.safety_factor * s.critical_time_step));
    }
    s.dt = sc.run.time_step;
  } else {
    s.dt = sc.run.safety_factor * s.critical_time_step;
  }

  bool settle_needed = false;
  SettleParams sp;
  for (const auto& src : sc.sources)
    if (src.settle.enabled) {
      settle_needed = true;
      sp = src.settle;
    }
  if (settle_needed && opt.settle) {
    s.settle_time = settle(*run, sp);
    s.time = 0.0;
    s.step = 0;
    for (auto& v : s.particles.v) v.setZero();
    for (auto& w : s.particles.w) w = Space<D>::rot_zero();
    for (auto& w : s.walls) {
      w.impulse.setZero();
      w.work = 0.0;
      w.reset_force_extremes();
    }
    for (auto& m : s.membranes) std::fill(m.body.v.begin(), m.body.v.end(), Vec3::Zero());
  }
  return run;
}

template std::unique_ptr<DemRun<2>> build_dem<2>(const DemScenario&, const BuildOptions&);
template std::unique_ptr<DemRun<3>> build_dem<3>(const DemScenario&, const BuildOptions&);

}  // namespace talus::dem
