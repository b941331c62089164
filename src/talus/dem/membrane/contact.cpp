#include "talus/dem/membrane/contact.hpp"

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"

namespace talus::dem::membrane {

TrianglePoint closest_on_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) {
  const Vec3 ab = b - a, ac = c - a, ap = x - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}, Feature::Vertex, 0};
  const Vec3 bp = x - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}, Feature::Vertex, 1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return {a + t * ab, {1 - t, t, 0}, Feature::Edge, 2};
  }
  const Vec3 cp = x - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}, Feature::Vertex, 2};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return {a + t * ac, {1 - t, 0, t}, Feature::Edge, 1};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + t * (c - b), {0, 1 - t, t}, Feature::Edge, 0};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {a + v * ab + w * ac, {1 - v - w, v, w}, Feature::Face, -1};
}

void select_contacts(const Mesh& mesh, std::span<const Vec3> x, const Vec3& centre, double radius,
                     std::span<const int> candidates, std::vector<TriangleContact>& out,
                     std::vector<TriangleContact>& scratch) {
  std::vector<TriangleContact>& touched = scratch;
  touched.clear();
  for (int t : candidates) {
    const auto& tri = mesh.triangles[t];
    const TrianglePoint p = closest_on_triangle(x[tri[0]], x[tri[1]], x[tri[2]], centre);
    const double d = (centre - p.point).norm();
    if (!(d < radius)) continue;
    TriangleContact c{t, p.kind, t, p.point, p.w, d};
    if (p.kind == Feature::Vertex) c.feature = tri[p.corner];
    if (p.kind == Feature::Edge) c.feature = mesh.triangle_edges[t][p.corner];
    touched.push_back(c);
  }
  // Distances equal to within round-off, and contact points that are one.
  const double same_distance = 1e-10 * radius, same_point = 1e-3 * radius;
  const TriangleContact* none = nullptr;
  auto hit_on = [&](int t) {  // a triangle has at most one closest point
    for (const auto& c : touched)
      if (c.triangle == t) return &c;
    return none;
  };
  // A vertex or edge contact is dropped when a triangle that contains the
  // vertex or edge has a higher-priority contact (the spec's rule) or one that
  // is closer: the feature's point is then not a local minimum of the distance
  // to the mesh, only a non-closest point of a patch whose closest point is
  // counted elsewhere. (On a flat sheet, a grain just beside a vertex on an
  // edge line also overlaps the edges at 60 degrees in the neighbouring
  // triangles, with equal priority; the priority rule alone counts those again.)
  auto outranked_by = [&](const TriangleContact& c, int t) {
    if (t == c.triangle) return false;
    const TriangleContact* h = hit_on(t);
    return h && (h->kind > c.kind || h->distance < c.distance - same_distance);
  };
  out.clear();  // the contacts kept
  for (const auto& c : touched) {
    bool outranked = false;
    if (c.kind == Feature::Edge) {
      const Edge& e = mesh.edges[c.feature];
      outranked = outranked_by(c, e.t0) || (e.t1 >= 0 && outranked_by(c, e.t1));
    } else if (c.kind == Feature::Vertex) {
      for (int k = mesh.vertex_triangle_start[c.feature];
           k < mesh.vertex_triangle_start[c.feature + 1] && !outranked; ++k)
        outranked = outranked_by(c, mesh.vertex_triangle_list[k]);
    }
    if (!outranked) out.push_back(c);
  }
  // One force per shared vertex or edge, and per contact point: near a
  // vertex, round-off may report the same point as a vertex, edge or face.
  // Nearest first; each contact is compared with those already kept, out[0, n).
  std::stable_sort(out.begin(), out.end(), [](const TriangleContact& a, const TriangleContact& b) {
    return a.distance < b.distance;
  });
  std::size_t n = 0;
  for (std::size_t j = 0; j < out.size(); ++j) {
    const TriangleContact& c = out[j];
    const bool seen = std::any_of(out.begin(), out.begin() + n, [&](const TriangleContact& k) {
      return (k.kind == c.kind && k.feature == c.feature) ||
             (k.point - c.point).squaredNorm() < same_point * same_point;
    });
    if (!seen) out[n++] = c;
  }
  out.resize(n);
}

namespace {
uint64_t feature_key(const TriangleContact& c) {
  return (static_cast<uint64_t>(c.kind) << 32) | static_cast<uint32_t>(c.feature);
}
}  // namespace

void ContactMemory::begin_step(int lanes) {
  previous_.clear();
  for (Lane& l : lanes_) {
    previous_.insert(previous_.end(), l.current.begin(), l.current.end());
    l.current.clear();
  }
  lanes_.resize(std::max(1, lanes));
  // Stable: a grain's entries keep their order (they come from one lane).
  std::stable_sort(previous_.begin(), previous_.end(),
                   [](const Entry& a, const Entry& b) { return a.grain < b.grain; });
  for (auto& e : previous_) e.continued = false;
}

std::size_t ContactMemory::size() const {
  std::size_t n = 0;
  for (const Lane& l : lanes_) n += l.current.size();
  return n;
}

std::span<ContactHistory<3>> ContactMemory::springs(int64_t grain,
                                                    std::span<const TriangleContact> contacts,
                                                    double radius, int lane) {
  std::vector<ContactHistory<3>>& out = lanes_[lane].springs;
  out.assign(contacts.size(), ContactHistory<3>{});
  auto lo = std::lower_bound(previous_.begin(), previous_.end(), grain,
                             [](const Entry& e, int64_t g) { return e.grain < g; });
  auto hi = lo;
  while (hi != previous_.end() && hi->grain == grain) ++hi;
  if (lo == hi) return out;
  std::vector<char>& found = lanes_[lane].found;
  found.assign(contacts.size(), 0);
  for (std::size_t k = 0; k < contacts.size(); ++k)
    for (auto it = lo; it != hi; ++it)
      if (!it->continued && it->feature == feature_key(contacts[k])) {
        out[k] = it->history;
        it->continued = true;
        found[k] = 1;
        break;
      }
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    if (found[k]) continue;
    auto best = hi;
    double best_d = radius;
    for (auto it = lo; it != hi; ++it) {
      const double d = (it->point - contacts[k].point).norm();
      if (!it->continued && d < best_d) {
        best = it;
        best_d = d;
      }
    }
    if (best != hi) {
      out[k] = best->history;
      best->continued = true;
    }
  }
  return out;
}

ContactMemory::Saved ContactMemory::saved() const {
  Saved s;
  for (const Lane& l : lanes_)
    for (const Entry& e : l.current) {
      s.grain.push_back(e.grain);
      s.feature.push_back(e.feature);
      s.point.push_back(e.point);
      s.shear.push_back(e.history.shear);
      s.roll.push_back(e.history.roll);
    }
  return s;
}

void ContactMemory::restore(const Saved& s) {
  const std::size_t n = s.grain.size();
  if (s.feature.size() != n || s.point.size() != n || s.shear.size() != n || s.roll.size() != n)
    throw InputError("membrane contact springs: arrays of different lengths");
  lanes_.assign(1, Lane{});
  previous_.clear();
  for (std::size_t k = 0; k < n; ++k)
    lanes_[0].current.push_back(
        {s.grain[k], s.feature[k], s.point[k], ContactHistory<3>{s.shear[k], s.roll[k]}, false});
}

void ContactMemory::store(int64_t grain, const TriangleContact& c, const ContactHistory<3>& h,
                          int lane) {
  lanes_[lane].current.push_back({grain, feature_key(c), c.point, h, false});
}

namespace {

// The contact forces of one grain; add_reaction(vertex, force) takes the
// membrane's share, m_eff(contact) is the contact's effective mass.
template <class AddReaction, class EffectiveMass>
GrainForce contact_forces(const Mesh& mesh, std::span<const Vec3> x_mem,
                          std::span<const Vec3> v_mem, AddReaction&& add_reaction,
                          EffectiveMass&& m_eff, int64_t grain_id, const Grain& g,
                          std::span<const TriangleContact> contacts,
                          const ContactLaw::Coeffs& coeffs, double dt, ContactMemory& memory,
                          int lane) {
  GrainForce out;
  if (contacts.empty()) return out;
  const std::span<ContactHistory<3>> springs = memory.springs(grain_id, contacts, g.radius, lane);
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const TriangleContact& c = contacts[k];
    const auto& tri = mesh.triangles[c.triangle];
    ContactKinematics<3> kin;
    if (c.distance > 0) {
      kin.n = (g.x - c.point) / c.distance;
    } else {  // centre on the membrane: push along the triangle's normal
      kin.n = (x_mem[tri[1]] - x_mem[tri[0]]).cross(x_mem[tri[2]] - x_mem[tri[0]]).normalized();
    }
    kin.overlap = g.radius - c.distance;
    // Lever arm to the membrane point c.point, where the reactions act (their
    // weighted sum of vertex positions): with the midpoint of the overlap
    // instead, each tangential force left a torque (overlap / 2) n x ft
    // unbalanced, and a free membrane body full of grains under vacuum spun up.
    const double arm = std::max(0.0, c.distance);
    kin.r_eff = g.radius;
    kin.m_eff = m_eff(c);
    kin.inertia_eff = 0;
    const Vec3 v_membrane =
        c.w[0] * v_mem[tri[0]] + c.w[1] * v_mem[tri[1]] + c.w[2] * v_mem[tri[2]];
    const Vec3 vrel = g.v - v_membrane;
    kin.vn = vrel.dot(kin.n);
    kin.vt = vrel - kin.vn * kin.n - (arm * g.w).cross(kin.n);
    kin.w_rel = g.w;
    ContactForce<3> cf;
    ContactLaw::compute<3>(coeffs, kin, springs[k], dt, cf);
    const Vec3 f = cf.fn * kin.n + cf.ft;
    out.force += f;
    out.torque += arm * (-kin.n.cross(cf.ft));
    for (int i = 0; i < 3; ++i) add_reaction(tri[i], Vec3(-c.w[i] * f));
    memory.store(grain_id, c, springs[k], lane);
    ++out.contacts;
  }
  return out;
}

}  // namespace

GrainForce grain_membrane_forces(const Mesh& mesh, std::span<const Vec3> x_mem,
                                 std::span<const Vec3> v_mem, std::span<Vec3> f_mem,
                                 int64_t grain_id, const Grain& g,
                                 std::span<const TriangleContact> contacts,
                                 const ContactLaw::Coeffs& coeffs, double dt,
                                 ContactMemory& memory) {
  return contact_forces(
      mesh, x_mem, v_mem, [&](int v, const Vec3& f) { f_mem[v] += f; },
      [&](const TriangleContact&) { return g.mass; }, grain_id, g, contacts, coeffs, dt, memory, 0);
}

GrainForce grain_membrane_forces(const Mesh& mesh, std::span<const Vec3> x_mem,
                                 std::span<const Vec3> v_mem,
                                 std::vector<std::pair<int, Vec3>>& reactions, int64_t grain_id,
                                 const Grain& g, std::span<const TriangleContact> contacts,
                                 const ContactLaw::Coeffs& coeffs, double dt, ContactMemory& memory,
                                 int lane) {
  return contact_forces(
      mesh, x_mem, v_mem, [&](int v, const Vec3& f) { reactions.emplace_back(v, f); },
      [&](const TriangleContact&) { return g.mass; }, grain_id, g, contacts, coeffs, dt, memory,
      lane);
}

GrainForce rigid_sphere_forces(const Mesh& mesh, std::span<const Vec3> x_mem,
                               std::span<const Vec3> v_mem, std::span<const double> mass,
                               std::span<Vec3> f_mem, int64_t sphere_id, const Grain& g,
                               std::span<const TriangleContact> contacts,
                               const ContactLaw::Coeffs& coeffs, double dt, ContactMemory& memory) {
  auto m_point = [&](const TriangleContact& c) {
    const auto& tri = mesh.triangles[c.triangle];
    double inv = 0.0;
    for (int k = 0; k < 3; ++k) inv += c.w[k] * c.w[k] / mass[tri[k]];
    return 1.0 / inv;
  };
  return contact_forces(
      mesh, x_mem, v_mem, [&](int k, const Vec3& r) { f_mem[k] += r; }, m_point, sphere_id, g,
      contacts, coeffs, dt, memory, 0);
}

int particle_triangle_forces(const Mesh& mesh, std::span<const Vec3> x, std::span<const Vec3> v,
                             std::span<const double> mass, std::span<Vec3> f, int particle,
                             double radius, std::span<const TriangleContact> contacts,
                             const ContactLaw::Coeffs& coeffs, double dt, ContactMemory& memory) {
  const Grain g{x[particle], v[particle], Vec3::Zero(), radius, mass[particle]};
  auto m_eff = [&](const TriangleContact& c) {
    const auto& tri = mesh.triangles[c.triangle];
    double inv = 0.0;
    for (int k = 0; k < 3; ++k) inv += c.w[k] * c.w[k] / mass[tri[k]];
    const double m_point = 1.0 / inv;
    return mass[particle] * m_point / (mass[particle] + m_point);
  };
  const GrainForce gf = contact_forces(
      mesh, x, v, [&](int k, const Vec3& r) { f[k] += r; }, m_eff, particle, g, contacts, coeffs,
      dt, memory, 0);
  f[particle] += gf.force;
  return gf.contacts;
}

Eigen::Vector3i TriangleGrid::cell_of(const Vec3& p) const {
  Eigen::Vector3i c;
  for (int d = 0; d < 3; ++d)
    c[d] = std::clamp(static_cast<int>(std::floor((p[d] - origin_[d]) / cell_)), 0, dims_[d] - 1);
  return c;
}

void TriangleGrid::build(const Mesh& mesh, std::span<const Vec3> x, double cell) {
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (const Vec3& p : x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  origin_ = lo;
  // No more cells than about 8 per triangle: a tiny cell for a large mesh
  // would only cost memory.
  const double volume_cells = 8.0 * mesh.num_triangles() + 64;
  const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-12));
  cell_ = std::max(cell, std::cbrt(extent.prod() / volume_cells));
  for (int d = 0; d < 3; ++d) dims_[d] = static_cast<int>(std::floor(extent[d] / cell_)) + 1;
  const std::size_t n_cells = static_cast<std::size_t>(dims_.prod());
  start_.assign(n_cells + 1, 0);
  auto for_cells = [&](int t, auto&& visit) {
    const auto& tri = mesh.triangles[t];
    const Vec3 tlo = x[tri[0]].cwiseMin(x[tri[1]]).cwiseMin(x[tri[2]]);
    const Vec3 thi = x[tri[0]].cwiseMax(x[tri[1]]).cwiseMax(x[tri[2]]);
    const Eigen::Vector3i a = cell_of(tlo), b = cell_of(thi);
    for (int i = a.x(); i <= b.x(); ++i)
      for (int j = a.y(); j <= b.y(); ++j)
        for (int k = a.z(); k <= b.z(); ++k) visit((k * dims_.y() + j) * dims_.x() + i);
  };
  const int nt = static_cast<int>(mesh.num_triangles());
  for (int t = 0; t < nt; ++t) for_cells(t, [&](int c) { ++start_[c + 1]; });
  for (std::size_t c = 0; c < n_cells; ++c) start_[c + 1] += start_[c];
  list_.assign(start_.back(), -1);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int t = 0; t < nt; ++t) for_cells(t, [&](int c) { list_[fill[c]++] = t; });
  centroid_.resize(mesh.num_triangles());
  bound_.resize(mesh.num_triangles());
  for (int t = 0; t < nt; ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3 c = (x[tri[0]] + x[tri[1]] + x[tri[2]]) / 3.0;
    centroid_[t] = c;
    bound_[t] = std::sqrt(std::max({(x[tri[0]] - c).squaredNorm(), (x[tri[1]] - c).squaredNorm(),
                                    (x[tri[2]] - c).squaredNorm()}));
  }
}

void TriangleGrid::query(const Vec3& centre, double radius, std::vector<int>& out,
                         Scratch& scratch) const {
  out.clear();
  if (scratch.stamp.size() != centroid_.size()) {
    scratch.stamp.assign(centroid_.size(), 0);
    scratch.id = 0;
  }
  if (++scratch.id == 0) {  // wrapped: reset the stamps
    std::fill(scratch.stamp.begin(), scratch.stamp.end(), 0);
    scratch.id = 1;
  }
  const Vec3 r = Vec3::Constant(radius);
  const Eigen::Vector3i a = cell_of(centre - r), b = cell_of(centre + r);
  for (int i = a.x(); i <= b.x(); ++i)
    for (int j = a.y(); j <= b.y(); ++j)
      for (int k = a.z(); k <= b.z(); ++k) {
        const int c = (k * dims_.y() + j) * dims_.x() + i;
        for (int q = start_[c]; q < start_[c + 1]; ++q) {
          const int t = list_[q];
          if (scratch.stamp[t] == scratch.id) continue;
          scratch.stamp[t] = scratch.id;
          // No point of the triangle is within radius of the centre when its
          // bounding sphere is not (most candidates of a grain near the mesh).
          const double reach = radius + bound_[t];
          if ((centre - centroid_[t]).squaredNorm() < reach * reach) out.push_back(t);
        }
      }
}

}  // namespace talus::dem::membrane
