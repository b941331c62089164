#include "talus/dem/output_observer.hpp"

#include <array>
#include <cmath>

#include "talus/dem/checkpoint.hpp"
#include "talus/io/csv_reader.hpp"

namespace talus::dem {

namespace {

template <int D>
std::vector<std::string> series_columns(const DemSystem<D>& s) {
  std::vector<std::string> c = {"time",
                                "step",
                                "particles",
                                "kinetic_energy",
                                "rotational_energy",
                                "potential_energy",
                                "pair_contacts",
                                "wall_contacts",
                                "removed",
                                "front_x",
                                "top"};
  const char* axes = "xyz";
  for (const auto& w : s.walls) {
    for (int d = 0; d < D; ++d) c.push_back(w.name + "_f" + axes[d]);
    for (int d = (D == 2 ? 2 : 0); d < 3; ++d) c.push_back(w.name + "_t" + axes[d]);
    for (int d = 0; d < D; ++d) c.push_back(w.name + "_impulse_" + axes[d]);
  }
  for (const auto& m : s.membranes) {
    c.push_back(m.name + "_kinetic_energy");
    for (int d = 0; d < 3; ++d) c.push_back(m.name + "_reaction_" + axes[d]);
    c.push_back(m.name + "_contacts");
    if (m.self_contact) c.push_back(m.name + "_self_contacts");
  }
  return c;
}

void add_polyline(io::WallFrame& f, const std::vector<Vec3>& pts, int wall) {
  const int base = static_cast<int>(f.points.size());
  f.points.insert(f.points.end(), pts.begin(), pts.end());
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    f.lines.push_back({base + static_cast<int>(k), base + static_cast<int>(k) + 1});
    f.line_wall.push_back(wall);
  }
}

void add_triangle(io::WallFrame& f, const Vec3& a, const Vec3& b, const Vec3& c, int wall) {
  const int base = static_cast<int>(f.points.size());
  f.points.insert(f.points.end(), {a, b, c});
  f.triangles.push_back({base, base + 1, base + 2});
  f.triangle_wall.push_back(wall);
}

Vec3 any_perpendicular(const Vec3& n) {
  const Vec3 t = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return n.cross(t).normalized();
}

// A sphere of 4 n (n - 1) triangles (n bands of latitude, 2 n of longitude).
void add_sphere(io::WallFrame& f, const Vec3& c, double r, int wall, int n = 8) {
  auto at = [&](int i, int j) {
    const double th = M_PI * i / n, ph = M_PI * j / n;
    return Vec3(c +
                r * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      if (i > 0) add_triangle(f, at(i, j), at(i + 1, j), at(i, j + 1), wall);
      if (i < n - 1) add_triangle(f, at(i, j + 1), at(i + 1, j), at(i + 1, j + 1), wall);
    }
}

}  // namespace

io::MeshFrame membrane_frame(const membrane::MembraneBody& m) {
  io::MeshFrame f;
  f.points = m.body.x;
  f.triangles = m.body.mesh.triangles;
  f.point_vectors["velocity"] = m.body.v;
  f.point_scalars["fixed"].assign(m.body.fixed.begin(), m.body.fixed.end());
  f.cell_scalars["tension"] = membrane::triangle_tension(m);
  return f;
}

template <int D>
io::WallFrame wall_frame(const DemSystem<D>& s, double extent) {
  io::WallFrame f;
  using geometry::PrimitiveKind;
  for (std::size_t w = 0; w < s.walls.size(); ++w) {
    if (!s.walls[w].active(s.time)) continue;
    const int wi = static_cast<int>(w);
    for (const auto& p : s.walls[w].current) {
      switch (p.kind) {
        case PrimitiveKind::Segment:
          add_polyline(f, {p.p0, p.p1}, wi);
          break;
        case PrimitiveKind::Arc: {
          std::vector<Vec3> pts;
          const int n = 32;
          for (int k = 0; k <= n; ++k) {
            const double a = p.angle_start + (p.angle_end - p.angle_start) * k / n;
            pts.push_back(p.p0 + p.radius * Vec3(std::cos(a), std::sin(a), 0.0));
          }
          add_polyline(f, pts, wi);
          break;
        }
        case PrimitiveKind::Plane: {
          if (D == 2) {
            const Vec3 t(-p.n.y(), p.n.x(), 0.0);
            add_polyline(f, {p.p0 - 0.5 * extent * t, p.p0 + 0.5 * extent * t}, wi);
          } else {
            const Vec3 u = any_perpendicular(p.n), v = p.n.cross(u);
            const double h = 0.5 * extent;
            const Vec3 a = p.p0 - h * u - h * v, b = p.p0 + h * u - h * v;
            const Vec3 c = p.p0 + h * u + h * v, d = p.p0 - h * u + h * v;
            add_triangle(f, a, b, c, wi);
            add_triangle(f, a, c, d, wi);
          }
          break;
        }
        case PrimitiveKind::Triangle:
          add_triangle(f, p.p0, p.p1, p.p2, wi);
          break;
        case PrimitiveKind::Cylinder: {
          const Vec3 u = any_perpendicular(p.n), v = p.n.cross(u);
          const double len = std::isfinite(p.length) ? p.length : extent;
          const int n = 24;
          for (int k = 0; k < n; ++k) {
            const double a0 = 2 * M_PI * k / n, a1 = 2 * M_PI * (k + 1) / n;
            const Vec3 r0 = p.radius * (std::cos(a0) * u + std::sin(a0) * v);
            const Vec3 r1 = p.radius * (std::cos(a1) * u + std::sin(a1) * v);
            const Vec3 top = len * p.n;
            add_triangle(f, p.p0 + r0, p.p0 + r1, p.p0 + r1 + top, wi);
            add_triangle(f, p.p0 + r0, p.p0 + r1 + top, p.p0 + r0 + top, wi);
          }
          break;
        }
      }
    }
  }
  // The driven spheres (the gripper's object), numbered after the walls.
  for (std::size_t o = 0; o < s.objects.size(); ++o)
    add_sphere(f, s.objects[o].x, s.objects[o].radius, static_cast<int>(s.walls.size() + o));
  return f;
}

template <int D>
DemOutputs<D>::DemOutputs(std::filesystem::path dir, const DemSystem<D>& s, bool resume,
                          double resume_time)
    : dir_(std::move(dir)) {
  std::filesystem::create_directories(dir_);
  const auto csv = dir_ / "series.csv";
  if (resume) io::CsvSeries::truncate_after(csv, resume_time);
  series_ = std::make_unique<io::CsvSeries>(csv, series_columns(s), resume);
  particles_ = std::make_unique<io::PvdSeries>(dir_, "particles", resume);
  walls_ = std::make_unique<io::PvdSeries>(dir_, "walls", resume);
  if (resume) {
    particles_->truncate_after(resume_time);
    walls_->truncate_after(resume_time);
  }
  for (const auto& m : s.membranes) {
    membranes_.push_back(std::make_unique<io::PvdSeries>(dir_, "membrane_" + m.name, resume));
    if (resume) membranes_.back()->truncate_after(resume_time);
  }
  peak_wall_force.assign(s.walls.size(), 0.0);
  if (resume) replay_peaks(io::read_csv(csv), s);
}

// The peaks of the rows the interrupted run wrote, in the order it wrote them:
// the values are CSV text of the shortest round-trip form, so the resumed run's
// summary gets the uninterrupted run's bits.
template <int D>
void DemOutputs<D>::replay_peaks(const io::CsvTable& table, const DemSystem<D>& s) {
  const std::size_t t = table.column("time"), ke = table.column("kinetic_energy");
  const char* axes = "xyz";
  std::vector<std::array<std::size_t, D>> force(s.walls.size());
  for (std::size_t w = 0; w < s.walls.size(); ++w)
    for (int d = 0; d < D; ++d) force[w][d] = table.column(s.walls[w].name + "_f" + axes[d]);
  for (const auto& row : table.rows) {
    for (std::size_t w = 0; w < s.walls.size(); ++w) {
      Vec3 f = Vec3::Zero();  // as Wall::force (z = 0 in 2D)
      for (int d = 0; d < D; ++d) f[d] = row[force[w][d]];
      peak_wall_force[w] = std::max(peak_wall_force[w], f.norm());
    }
    if (row[ke] > peak_kinetic_energy) {
      peak_kinetic_energy = row[ke];
      peak_kinetic_energy_time = row[t];
    }
  }
}

template <int D>
void DemOutputs<D>::on_series(const DemRun<D>& run) {
  const auto& s = run.system;
  const auto& p = s.particles;
  const double ke = kinetic_energy(p);
  std::vector<double> row = {s.time,
                             static_cast<double>(s.step),
                             static_cast<double>(p.size()),
                             ke,
                             rotational_energy(p),
                             potential_energy(p, s.gravity),
                             static_cast<double>(s.pair_contacts),
                             static_cast<double>(s.wall_contacts),
                             static_cast<double>(s.removed),
                             front_x(p),
                             top(p)};
  for (std::size_t w = 0; w < s.walls.size(); ++w) {
    const auto& wall = s.walls[w];
    for (int d = 0; d < D; ++d) row.push_back(wall.force[d]);
    for (int d = (D == 2 ? 2 : 0); d < 3; ++d) row.push_back(wall.torque[d]);
    for (int d = 0; d < D; ++d) row.push_back(wall.impulse[d]);
    peak_wall_force[w] = std::max(peak_wall_force[w], wall.force.norm());
  }
  for (const auto& m : s.membranes) {
    row.push_back(membrane::kinetic_energy(m));
    for (int d = 0; d < 3; ++d) row.push_back(m.reaction[d]);
    row.push_back(m.contacts);
    if (m.self_contact) row.push_back(m.self_contacts);
  }
  if (ke > peak_kinetic_energy) {
    peak_kinetic_energy = ke;
    peak_kinetic_energy_time = s.time;
  }
  series_->row(row);
}

template <int D>
void DemOutputs<D>::on_snapshot(const DemRun<D>& run) {
  const auto& s = run.system;
  const auto& p = s.particles;
  io::ParticleFrame f;
  const std::size_t n = p.size();
  f.position.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    f.position.push_back(Space<D>::to3(p.x[i]));
    f.velocity.push_back(Space<D>::to3(p.v[i]));
    f.angular_velocity.push_back(Space<D>::rot_to3(p.w[i]));
    f.contacts.push_back(p.contacts[i] + p.wall_contacts[i]);
  }
  f.radius = p.r;
  f.id = p.id;
  f.material = p.material;
  if (decorate) decorate(s, f);
  particles_->add(s.time, f);
  double extent = 1.0;
  if (s.has_domain()) extent = (s.domain_max - s.domain_min).maxCoeff();
  walls_->add(s.time, wall_frame(s, extent));
  for (std::size_t k = 0; k < s.membranes.size(); ++k)
    membranes_[k]->add(s.time, membrane_frame(s.membranes[k]));
}

template <int D>
void DemOutputs<D>::on_checkpoint(const DemRun<D>& run) {
  series_->flush();
  run.stepper->sync_lists();
  save_checkpoint(run.system, checkpoint_path(dir_));
}

template <int D>
void DemOutputs<D>::flush() {
  series_->flush();
}

template class DemOutputs<2>;
template class DemOutputs<3>;
template io::WallFrame wall_frame<2>(const DemSystem<2>&, double);
template io::WallFrame wall_frame<3>(const DemSystem<3>&, double);

}  // namespace talus::dem
