#include "talus/dem/packing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "talus/core/error.hpp"

// Internally everything works in a normalised frame: lengths in units of the mean final radius,
// measured from the region's lower corner, so that overlaps, tolerances and time steps are O(1)
// whatever the particle size. Both generators relax overlaps with FIRE (Bitzek et al. 2006, with
// the FIRE 2.0 tweaks of Guenole et al. 2020) on the energy U = 1/2 sum(overlap^2) of unit
// springs and unit masses.

namespace talus::dem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Final boundary projection keeps the centre this far beyond `radius`, so that contains() holds
// after the conversion back to metres.
constexpr double kInsideSlack = 1e-9;

// std::uniform_real_distribution differs between standard libraries; this does not.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

template <int D>
double ball_volume(double r) {
  return Space<D>::volume(r);
}

struct Stats {
  double energy = 0.0, max_overlap = 0.0, sum_overlap = 0.0, max_wall = 0.0;
  int pairs = 0;
  double mean() const { return pairs > 0 ? sum_overlap / pairs : 0.0; }
  void add_wall(double penetration) {
    energy += 0.5 * penetration * penetration;
    max_wall = std::max(max_wall, penetration);
  }
};

double twice_signed_area(const std::vector<Vec3>& polygon) {
  double sum = 0.0;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Vec3 &a = polygon[k], &b = polygon[(k + 1) % polygon.size()];
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

template <int D>
struct Walls;

// 2D: a polygon, counter-clockwise after construction. Penalty for a disk inside: one spring per
// edge it overlaps (continuous, and it pushes out of sharp corners along the bisector). For a
// centre outside, one spring to the nearest boundary point that pulls it back in.
template <>
struct Walls<2> {
  using V = Vec<2>;
  std::vector<V> vertex, inward, corner;  // corner: inward pseudonormal at the vertex
  V lo, hi;

  Walls(const Region& region, const Vec3& origin, double unit) {
    std::vector<Vec3> pts = region.polygon;
    if (pts.empty()) {
      const Vec3 &a = region.box_min, &b = region.box_max;
      pts = {a, Vec3(b.x(), a.y(), 0), b, Vec3(a.x(), b.y(), 0)};
    }
    if (twice_signed_area(pts) < 0) std::reverse(pts.begin(), pts.end());
    for (const Vec3& p : pts) {  // repeated points (a closing copy of the first) would have no edge
      const V q = (p - origin).head<2>() / unit;
      if (vertex.empty() || q != vertex.back()) vertex.push_back(q);
    }
    if (vertex.size() > 1 && vertex.front() == vertex.back()) vertex.pop_back();
    const size_t n = vertex.size();
    for (size_t k = 0; k < n; ++k) {
      const V d = (vertex[(k + 1) % n] - vertex[k]).normalized();
      inward.push_back(V(-d.y(), d.x()));
    }
    for (size_t k = 0; k < n; ++k)
      corner.push_back((inward[(k + n - 1) % n] + inward[k]).normalized());
    lo = hi = vertex[0];
    for (const V& p : vertex) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  int size() const { return static_cast<int>(vertex.size()); }

  struct Closest {
    double dist;
    V q;
    bool inside;  // what the nearest feature says about the side of p
  };
  Closest closest(int k, const V& p) const {
    const int n = size(), k1 = (k + 1) % n;
    const V d = vertex[k1] - vertex[k];
    const double t = std::clamp((p - vertex[k]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const V q = vertex[k] + t * d;
    const V& normal = t <= 0.0 ? corner[k] : (t >= 1.0 ? corner[k1] : inward[k]);
    return {(p - q).norm(), q, (p - q).dot(normal) >= 0.0};
  }
  // Signed distance to the boundary (positive inside) and its gradient.
  double signed_distance(const V& p, V* gradient = nullptr) const {
    Closest best{kInf, V::Zero(), true};
    int best_k = 0;
    for (int k = 0; k < size(); ++k) {
      const Closest c = closest(k, p);
      if (c.dist < best.dist) best = c, best_k = k;
    }
    if (gradient) {
      *gradient =
          best.dist > 0 ? V((best.inside ? 1.0 : -1.0) * (p - best.q) / best.dist) : inward[best_k];
    }
    return best.inside ? best.dist : -best.dist;
  }
  void candidates(const V& p, double reach, std::vector<int>& out) const {
    for (int k = 0; k < size(); ++k)
      if (closest(k, p).dist < reach) out.push_back(k);
  }
  void add_force(const V& p, double r, const int* ids, int n, V& f, Stats& s) const {
    if (n == 0) return;
    std::array<Closest, 8> near;
    Closest nearest{kInf, V::Zero(), true};
    for (int c = 0; c < n; ++c) {
      const Closest cl = closest(ids[c], p);
      if (c < 8) near[c] = cl;
      if (cl.dist < nearest.dist) nearest = cl;
    }
    if (!nearest.inside || nearest.dist == 0.0) {
      V gradient;
      const double penetration = r - signed_distance(p, &gradient);
      f += penetration * gradient;
      s.add_wall(penetration);
      return;
    }
    for (int c = 0; c < n; ++c) {
      const Closest cl = c < 8 ? near[c] : closest(ids[c], p);
      if (cl.dist >= r) continue;
      f += (r - cl.dist) / cl.dist * (p - cl.q);
      s.add_wall(r - cl.dist);
    }
  }
  void project_inside(V& p, double r) const {
    const double target = r * (1.0 + kInsideSlack);
    for (int pass = 0; pass < 200; ++pass) {  // alternating projections out of corners
      V gradient;
      const double sd = signed_distance(p, &gradient);
      if (sd >= target) return;
      p += (target - sd + 1e-12 * r) * gradient;
    }
  }
};

// 3D: the box; each face is a plane, and a sum of plane springs is exact for a convex region.
// A cylinder keeps the two z faces (4, 5) and replaces the four side faces by its mantle (face 6).
// A spherical shell has only its outer sphere (face 7) and inner sphere (face 8): the springs act
// along the radius, and the inner one is the only non-convex boundary, whose spring is still
// exact since a ball touches a sphere in one point. A box with rounded edges is one face (9): the
// distance to the box shrunk by the edge radius, less that radius (convex, so one spring along
// the gradient is exact).
template <>
struct Walls<3> {
  using V = Vec<3>;
  V lo, hi;
  double radius = 0.0;  // > 0: cylinder about the vertical axis through `axis`
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();
  double outer = 0.0, inner = 0.0;  // outer > 0: spherical shell about `centre`
  V centre = V::Zero();
  double edge = 0.0;  // > 0: the box's edges and corners rounded with this radius
  Walls(const Region& region, const Vec3& origin, double unit)
      : lo((region.box_min - origin) / unit), hi((region.box_max - origin) / unit) {
    edge = region.edge_radius / unit;
    if (region.cylinder_radius > 0) {
      radius = region.cylinder_radius / unit;
      axis = 0.5 * (lo + hi).head<2>();
    }
    if (region.shell_outer_radius > 0) {
      outer = region.shell_outer_radius / unit;
      inner = region.shell_inner_radius / unit;
      centre = 0.5 * (lo + hi);
    }
  }
  int first_face() const { return edge > 0 ? 9 : outer > 0 ? 7 : radius > 0 ? 4 : 0; }
  int last_face() const { return edge > 0 ? 10 : outer > 0 ? 9 : radius > 0 ? 7 : 6; }
  // The rounded box is the core box (the box shrunk by the edge radius) swept by a ball of that
  // radius: p's nearest point in the core.
  V nearest_in_core(const V& p) const {
    return p.cwiseMax(V(lo.array() + edge)).cwiseMin(V(hi.array() - edge));
  }
  // The rounded box: signed distance (positive inside) and the inward direction.
  double rounded_distance(const V& p, V* inward = nullptr) const {
    const V out = p - nearest_in_core(p);
    const double len = out.norm();
    if (len > 0) {
      if (inward) *inward = -out / len;
      return edge - len;
    }
    double best = kInf;  // inside the core: the nearest flat face
    for (int face = 0; face < 6; ++face) {
      const int a = face / 2;
      const double d = face % 2 == 0 ? p[a] - lo[a] : hi[a] - p[a];
      if (d < best) {
        best = d;
        if (inward) *inward = (face % 2 == 0 ? 1.0 : -1.0) * V::Unit(a);
      }
    }
    return best;
  }
  double face_distance(int face, const V& p) const {
    if (face == 9) return rounded_distance(p);
    if (face == 7) return outer - (p - centre).norm();
    if (face == 8) return (p - centre).norm() - inner;
    if (face == 6) return radius - (p.head<2>() - axis).norm();
    const int a = face / 2;
    return face % 2 == 0 ? p[a] - lo[a] : hi[a] - p[a];
  }
  double signed_distance(const V& p) const {
    double d = kInf;
    for (int face = first_face(); face < last_face(); ++face)
      d = std::min(d, face_distance(face, p));
    return d;
  }
  void candidates(const V& p, double reach, std::vector<int>& out) const {
    for (int face = first_face(); face < last_face(); ++face)
      if (face_distance(face, p) < reach) out.push_back(face);
  }
  void add_force(const V& p, double r, const int* ids, int n, V& f, Stats& s) const {
    for (int c = 0; c < n; ++c) {
      const double penetration = r - face_distance(ids[c], p);
      if (penetration <= 0) continue;
      if (ids[c] == 9) {
        V inward = V::Zero();
        rounded_distance(p, &inward);
        f += penetration * inward;
      } else if (ids[c] == 7 || ids[c] == 8) {  // along the radius, inwards from the outer sphere
        const V d = p - centre;
        const double len = d.norm();
        if (len > 0) f += (ids[c] == 7 ? -penetration : penetration) / len * d;
      } else if (ids[c] == 6) {  // towards the axis
        const Eigen::Vector2d d = p.head<2>() - axis;
        const double len = d.norm();
        if (len > 0) f.head<2>() -= penetration / len * d;
      } else {
        f[ids[c] / 2] += ids[c] % 2 == 0 ? penetration : -penetration;
      }
      s.add_wall(penetration);
    }
  }
  void project_inside(V& p, double r) const {
    const double margin = r * (1.0 + kInsideSlack) + 1e-12 * r;
    if (outer > 0) {  // along the radius into the band of radii where the ball fits
      const V d = p - centre;
      const double len = d.norm(), lo_r = inner + margin, hi_r = std::max(lo_r, outer - margin);
      const double want = std::clamp(len, lo_r, hi_r);
      if (want != len) p = centre + (len > 0 ? V(d * (want / len)) : V(V::UnitX() * want));
      return;
    }
    for (int a = radius > 0 ? 2 : 0; a < 3; ++a)
      p[a] = hi[a] - lo[a] > 2 * margin ? std::clamp(p[a], lo[a] + margin, hi[a] - margin)
                                        : 0.5 * (lo[a] + hi[a]);
    if (radius > 0) {
      const Eigen::Vector2d d = p.head<2>() - axis;
      const double len = d.norm(), reach = std::max(0.0, radius - margin);
      if (len > reach) p.head<2>() = axis + (len > 0 ? Eigen::Vector2d(d * (reach / len)) : d);
    }
    if (edge > margin) {  // onto the rounded box shrunk by the margin (the clamp did the rest)
      const V core = nearest_in_core(p);
      const V out = p - core;
      const double len = out.norm(), reach = edge - margin;
      if (len > reach) p = core + out * (reach / len);
    }
  }
};

// Uniform cells with linked lists: each cell at least `h` wide, at most a few cells per particle.
template <int D>
struct Grid {
  Vec<D> lo;
  Vec<D> inv_size;
  std::array<int, D> n;
  std::vector<int> head, next;

  Grid(const Vec<D>& low, const Vec<D>& high, double h, int particles) : lo(low) {
    const Vec<D> extent = (high - low).cwiseMax(h);
    for (;; h *= 1.26) {
      long long cells = 1;
      for (int a = 0; a < D; ++a)
        n[a] = std::max(1, static_cast<int>(extent[a] / h)), cells *= n[a];
      if (cells <= std::max(64LL, 4LL * particles)) break;
    }
    for (int a = 0; a < D; ++a) inv_size[a] = n[a] / extent[a];
    head.assign(cells_total(), -1);
    next.assign(particles, -1);
  }
  int cells_total() const {
    int c = 1;
    for (int a = 0; a < D; ++a) c *= n[a];
    return c;
  }
  std::array<int, D> cell(const Vec<D>& p) const {
    std::array<int, D> c;
    for (int a = 0; a < D; ++a)
      c[a] = std::clamp(static_cast<int>(std::floor((p[a] - lo[a]) * inv_size[a])), 0, n[a] - 1);
    return c;
  }
  int index(const std::array<int, D>& c) const {
    int i = 0;
    for (int a = D - 1; a >= 0; --a) i = i * n[a] + c[a];
    return i;
  }
  void insert(int i, const Vec<D>& p) {
    const int c = index(cell(p));
    next[i] = head[c];
    head[c] = i;
  }
  // Calls visit(j) for every particle in the 3^D cells around p.
  template <class Visit>
  void for_near(const Vec<D>& p, Visit visit) const {
    const std::array<int, D> c = cell(p);
    std::array<int, D> lo_c, hi_c, it;
    for (int a = 0; a < D; ++a)
      lo_c[a] = std::max(0, c[a] - 1), hi_c[a] = std::min(n[a] - 1, c[a] + 1);
    it = lo_c;
    for (;;) {
      for (int j = head[index(it)]; j >= 0; j = next[j]) visit(j);
      int a = 0;
      while (a < D && ++it[a] > hi_c[a]) it[a] = lo_c[a], ++a;
      if (a == D) return;
    }
  }
};

struct Goal {
  double max_overlap;  // pairs and walls
  double mean_overlap;
  int max_iterations;
};

template <int D>
class Relaxer {
 public:
  using V = Vec<D>;
  std::vector<V> x;
  std::vector<double> r;

  Relaxer(const Walls<D>& walls, std::vector<V> positions, std::vector<double> radii)
      : x(std::move(positions)), r(std::move(radii)), walls_(walls) {
    v_.assign(x.size(), V::Zero());
    f_.assign(x.size(), V::Zero());
    build();
  }
  void set_radii(std::vector<double> radii) {
    r = std::move(radii);
    build();
  }
  // FIRE until the goal holds (true), or until the energy stops falling or the iteration budget
  // is spent (false: jammed, or not there yet).
  bool relax(const Goal& goal) {
    // dt_max: unit springs and masses, stable below about 2/sqrt(2 z) for z contacts.
    const double dt_max = 0.5, dt_min = 0.005, f_inc = 1.1, f_dec = 0.5, alpha0 = 0.1,
                 f_alpha = 0.99;
    const int delay = 5, window = 1000;
    double dt = 0.1, alpha = alpha0, window_min = kInf, previous_window_min = kInf;
    int positive_steps = 0;
    std::fill(v_.begin(), v_.end(), V::Zero());
    for (int iteration = 0;; ++iteration) {
      const Stats s = forces();
      if (std::max(s.max_overlap, s.max_wall) <= goal.max_overlap && s.mean() <= goal.mean_overlap)
        return true;
      if (iteration >= goal.max_iterations) return false;
      window_min = std::min(window_min, s.energy);
      if (iteration % window == window - 1) {
        if (window_min > 0.98 * previous_window_min) return false;
        previous_window_min = window_min;
        window_min = kInf;
      }
      double power = 0.0;
      for (size_t i = 0; i < x.size(); ++i) power += f_[i].dot(v_[i]);
      if (power >= 0) {  // == 0 only at the start, from rest
        if (++positive_steps > delay) dt = std::min(dt * f_inc, dt_max), alpha *= f_alpha;
      } else {
        positive_steps = 0;
        dt = std::max(dt * f_dec, dt_min);
        alpha = alpha0;
        for (size_t i = 0; i < x.size(); ++i) x[i] -= 0.5 * dt * v_[i], v_[i].setZero();
      }
      double v2 = 0.0, f2 = 0.0;
      for (size_t i = 0; i < x.size(); ++i) {
        v_[i] += dt * f_[i];
        v2 += v_[i].squaredNorm();
        f2 += f_[i].squaredNorm();
      }
      const double mix = f2 > 0 ? alpha * std::sqrt(v2 / f2) : 0.0;
      double moved2 = 0.0;
      for (size_t i = 0; i < x.size(); ++i) {
        v_[i] = (1.0 - alpha) * v_[i] + mix * f_[i];
        x[i] += dt * v_[i];
        moved2 = std::max(moved2, (x[i] - built_at_[i]).squaredNorm());
      }
      if (4.0 * moved2 > kSkin * kSkin) build();
    }
  }

 private:
  static constexpr double kSkin = 0.3;  // Verlet skin, in mean radii

  void build() {
    const int n = static_cast<int>(x.size());
    const double r_max = *std::max_element(r.begin(), r.end());
    Grid<D> grid(walls_.lo, walls_.hi, 2 * r_max + kSkin, n);
    pairs_.clear();
    for (int i = 0; i < n; ++i) {
      // A centre far outside would feel no wall: put it back (does not happen in practice).
      if (walls_.signed_distance(x[i]) < -0.5 * r[i]) walls_.project_inside(x[i], r[i]);
      grid.for_near(x[i], [&](int j) {
        const double reach = r[i] + r[j] + kSkin;
        if ((x[i] - x[j]).squaredNorm() < reach * reach) pairs_.push_back({j, i});
      });
      grid.insert(i, x[i]);
    }
    wall_start_.assign(1, 0);
    wall_ids_.clear();
    for (int i = 0; i < n; ++i) {
      walls_.candidates(x[i], r[i] + kSkin, wall_ids_);
      wall_start_.push_back(static_cast<int>(wall_ids_.size()));
    }
    built_at_ = x;
  }
  Stats forces() {
    Stats s;
    std::fill(f_.begin(), f_.end(), V::Zero());
    for (const auto& [i, j] : pairs_) {
      const V d = x[i] - x[j];
      const double reach = r[i] + r[j], dist2 = d.squaredNorm();
      if (dist2 >= reach * reach) continue;
      const double dist = std::sqrt(dist2), overlap = reach - dist;
      const V push = dist > 0 ? V(overlap / dist * d) : V(V::Unit(0) * overlap);
      f_[i] += push;
      f_[j] -= push;
      s.energy += 0.5 * overlap * overlap;
      s.max_overlap = std::max(s.max_overlap, overlap);
      s.sum_overlap += overlap;
      ++s.pairs;
    }
    for (size_t i = 0; i < x.size(); ++i)
      walls_.add_force(x[i], r[i], &wall_ids_[wall_start_[i]], wall_start_[i + 1] - wall_start_[i],
                       f_[i], s);
    return s;
  }

  const Walls<D>& walls_;
  std::vector<V> v_, f_, built_at_;
  std::vector<std::array<int, 2>> pairs_;
  std::vector<int> wall_start_, wall_ids_;
};

// Random sequential addition, largest first (the small ones fill the gaps that are left).
template <int D>
std::vector<Vec<D>> place_without_overlap(const Walls<D>& walls, const std::vector<double>& r,
                                          std::mt19937_64& rng) {
  const int n = static_cast<int>(r.size());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return r[a] > r[b]; });
  Grid<D> grid(walls.lo, walls.hi, 2 * r[order[0]], n);
  std::vector<Vec<D>> x(n);
  for (int i : order) {
    bool placed = false;
    for (int attempt = 0; attempt < 100000 && !placed; ++attempt) {
      Vec<D> p;
      for (int a = 0; a < D; ++a) p[a] = walls.lo[a] + uniform01(rng) * (walls.hi[a] - walls.lo[a]);
      if (walls.signed_distance(p) < r[i]) continue;
      placed = true;
      grid.for_near(p, [&](int j) {
        if ((p - x[j]).squaredNorm() < (r[i] + r[j]) * (r[i] + r[j])) placed = false;
      });
      if (placed) x[i] = p, grid.insert(i, p);
    }
    if (!placed)
      throw InputError(
          "packing: no room to place the particles even at reduced size: the region is too "
          "small for this count and these radii");
  }
  return x;
}

void check_inputs(const Region& region, double r_min, double r_max) {
  if (region.dimension != 2 && region.dimension != 3)
    throw InputError("packing: region.dimension must be 2 or 3");
  if (region.dimension == 2 && !region.polygon.empty() && region.polygon.size() < 3)
    throw InputError("packing: region.polygon needs at least 3 vertices");
  if (!(region.area_or_volume() > 0)) throw InputError("packing: region has no area or volume");
  if (!(r_min > 0) || !(r_max >= r_min))
    throw InputError(
        fmt::format("packing: need 0 < r_min <= r_max, got r_min = {}, r_max = {}", r_min, r_max));
}

// The problem in the normalised frame: radii scaled so that they fill `solid_fraction`.
template <int D>
struct Problem {
  Vec3 origin;
  double unit;  // metres per internal length
  std::vector<double> radius;

  Problem(const Region& region, double r_min, double r_max, double solid_fraction, int count,
          std::mt19937_64& rng) {
    std::vector<double> drawn(count);
    double solid = 0.0;
    for (double& r : drawn)
      r = r_min + (r_max - r_min) * uniform01(rng), solid += ball_volume<D>(r);
    const double scale = std::pow(solid_fraction * region.area_or_volume() / solid, 1.0 / D);
    unit = scale * 0.5 * (r_min + r_max);
    for (double r : drawn) radius.push_back(r * scale / unit);
    origin = region.dimension == 3 || region.polygon.empty() ? region.box_min : region.polygon[0];
  }
  std::vector<double> scaled(double s) const {
    std::vector<double> out(radius);
    for (double& r : out) r *= s;
    return out;
  }
  std::vector<PackedParticle> to_metres(const std::vector<Vec<D>>& x,
                                        const std::vector<double>& r) const {
    std::vector<PackedParticle> out(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      out[i].position = origin;
      out[i].position.template head<D>() += unit * x[i];
      out[i].radius = unit * r[i];
    }
    return out;
  }
};

// Solid fraction at which the random placement starts (well below random sequential jamming).
template <int D>
double placement_fraction() {
  return D == 2 ? 0.35 : 0.2;
}

template <int D>
std::vector<PackedParticle> fill(const Region& region, double r_min, double r_max, double phi,
                                 int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  const Problem<D> problem(region, r_min, r_max, phi, count, rng);
  const Walls<D> walls(region, problem.origin, problem.unit);
  const double phi0 = std::min(phi, placement_fraction<D>());
  Relaxer<D> relaxer(
      walls, place_without_overlap(walls, problem.scaled(std::pow(phi0 / phi, 1.0 / D)), rng),
      problem.radius);
  // Grow in stages: each relaxation starts from small overlaps, so no particle jumps a neighbour.
  const int stages = 12;
  for (int k = 1; k <= stages; ++k) {
    const double phi_k = phi0 + (phi - phi0) * k / stages;
    relaxer.set_radii(problem.scaled(std::pow(phi_k / phi, 1.0 / D)));
    // Intermediate stages only need small overlaps; the last one runs until the overlaps are
    // negligible or the energy stops falling (jammed).
    const Goal goal = k < stages ? Goal{0.02, 1e-3, 500} : Goal{1e-4, 1e-5, 40000};
    relaxer.relax(goal);
  }
  for (size_t i = 0; i < relaxer.x.size(); ++i) walls.project_inside(relaxer.x[i], relaxer.r[i]);
  std::vector<PackedParticle> out = problem.to_metres(relaxer.x, relaxer.r);
  const OverlapStats stats = overlap_stats(region, out);
  if (stats.mean_overlap > 0.005 * r_min)
    throw InputError(fmt::format(
        "packing: porosity {:.4f} is not reachable with radii {}..{} (jammed: mean overlap "
        "{:.2f} % of r_min after relaxation); ask for a larger porosity or fewer particles",
        1 - phi, r_min, r_max, 100 * stats.mean_overlap / r_min));
  return out;
}

template <int D>
GrowResult grow(const Region& region, double r_min, double r_max, double phi, int count,
                unsigned seed) {
  std::mt19937_64 rng(seed);
  const Problem<D> problem(region, r_min, r_max, phi, count, rng);
  const Walls<D> walls(region, problem.origin, problem.unit);
  double reached = std::min(phi, placement_fraction<D>());
  auto scale_at = [&](double fraction) { return std::pow(fraction / phi, 1.0 / D); };
  Relaxer<D> relaxer(walls, place_without_overlap(walls, problem.scaled(scale_at(reached)), rng),
                     problem.radius);
  // Relax at radii inflated by kInflate: when no inflated overlap exceeds kInflate * r_min, the
  // true radii overlap nowhere.
  const double kInflate = 1e-3;
  const double r_smallest = *std::min_element(problem.radius.begin(), problem.radius.end());
  std::vector<Vec<D>> accepted = relaxer.x;
  double step = 0.05;  // relative growth of the fraction per stage
  bool jammed = false;
  while (reached < phi && !jammed) {
    const double trial = std::min(phi, reached * (1 + step));
    relaxer.x = accepted;
    relaxer.set_radii(problem.scaled(scale_at(trial) * (1 + kInflate)));
    const double tolerance = kInflate * r_smallest * scale_at(trial);
    if (relaxer.relax({tolerance, kInf, 20000})) {
      accepted = relaxer.x;
      reached = trial;
    } else if ((step *= 0.5) < 1e-4) {
      jammed = true;
    }
  }
  return {problem.to_metres(accepted, problem.scaled(scale_at(reached))), reached, jammed};
}

template <int D>
OverlapStats stats_of(const Region& region, const std::vector<PackedParticle>& particles) {
  OverlapStats out;
  if (particles.empty()) return out;
  const Walls<D> walls(region, Vec3::Zero(), 1.0);
  double r_max = 0.0;
  for (const PackedParticle& p : particles) r_max = std::max(r_max, p.radius);
  Grid<D> grid(walls.lo, walls.hi, 2 * r_max, static_cast<int>(particles.size()));
  double sum = 0.0;
  for (int i = 0; i < static_cast<int>(particles.size()); ++i) {
    const Vec<D> xi = particles[i].position.head<D>();
    const double ri = particles[i].radius;
    grid.for_near(xi, [&](int j) {
      const double overlap =
          ri + particles[j].radius - (xi - particles[j].position.head<D>()).norm();
      if (overlap <= 0) return;
      out.max_overlap = std::max(out.max_overlap, overlap);
      sum += overlap;
      ++out.overlapping_pairs;
    });
    grid.insert(i, xi);
    out.max_wall_penetration = std::max(out.max_wall_penetration, ri - walls.signed_distance(xi));
  }
  out.mean_overlap = out.overlapping_pairs > 0 ? sum / out.overlapping_pairs : 0.0;
  return out;
}

}  // namespace

double Region::area_or_volume() const {
  if (dimension == 3 && shell_outer_radius > 0)
    return 4.0 / 3.0 * M_PI * (std::pow(shell_outer_radius, 3) - std::pow(shell_inner_radius, 3));
  if (dimension == 3 && cylinder_radius > 0)
    return M_PI * cylinder_radius * cylinder_radius * (box_max.z() - box_min.z());
  if (dimension == 3 && edge_radius > 0) {  // the core box swept by a ball of the edge radius
    const Vec3 c = (box_max - box_min).array() - 2 * edge_radius;
    const double e = edge_radius;
    return c.prod() + 2 * e * (c.x() * c.y() + c.y() * c.z() + c.z() * c.x()) +
           M_PI * e * e * c.sum() + 4.0 / 3.0 * M_PI * e * e * e;
  }
  if (dimension == 3) return (box_max - box_min).prod();
  if (polygon.empty()) return (box_max - box_min).head<2>().prod();
  return 0.5 * std::abs(twice_signed_area(polygon));
}

bool Region::contains(const Vec3& p, double margin) const {
  if (dimension == 3) return Walls<3>(*this, Vec3::Zero(), 1.0).signed_distance(p) >= margin;
  return Walls<2>(*this, Vec3::Zero(), 1.0).signed_distance(p.head<2>()) >= margin;
}

std::vector<PackedParticle> random_fill(const Region& region, double r_min, double r_max,
                                        double porosity, std::optional<int> count, unsigned seed) {
  check_inputs(region, r_min, r_max);
  if (!(porosity > 0 && porosity < 1))
    throw InputError(fmt::format("packing: porosity must lie in (0, 1), got {}", porosity));
  const int n = count ? *count : particle_count_for_porosity(region, r_min, r_max, porosity);
  if (n <= 0) throw InputError(fmt::format("packing: particle count must be > 0, got {}", n));
  return region.dimension == 2 ? fill<2>(region, r_min, r_max, 1 - porosity, n, seed)
                               : fill<3>(region, r_min, r_max, 1 - porosity, n, seed);
}

GrowResult grow_packing(const Region& region, double r_min, double r_max, double target_fraction,
                        int count, unsigned seed) {
  check_inputs(region, r_min, r_max);
  if (!(target_fraction > 0 && target_fraction < 1))
    throw InputError(
        fmt::format("packing: target fraction must lie in (0, 1), got {}", target_fraction));
  if (count <= 0) throw InputError(fmt::format("packing: count must be > 0, got {}", count));
  return region.dimension == 2 ? grow<2>(region, r_min, r_max, target_fraction, count, seed)
                               : grow<3>(region, r_min, r_max, target_fraction, count, seed);
}

void shrink_radii(std::vector<PackedParticle>& particles, double shrink) {
  for (PackedParticle& p : particles) p.radius *= 1.0 - shrink;
}

double porosity(const Region& region, const std::vector<PackedParticle>& particles) {
  double solid = 0.0;
  for (const PackedParticle& p : particles)
    solid += region.dimension == 2 ? Space<2>::volume(p.radius) : Space<3>::volume(p.radius);
  return 1.0 - solid / region.area_or_volume();
}

int particle_count_for_porosity(const Region& region, double r_min, double r_max, double porosity) {
  // Uniform radii: rbar = (r_min + r_max)/2, <r^3> = (r_min + r_max)(r_min^2 + r_max^2)/4.
  const double per_particle = region.dimension == 2 ? M_PI * std::pow(0.5 * (r_min + r_max), 2)
                                                    : 4.0 / 3.0 * M_PI * (r_min + r_max) *
                                                          (r_min * r_min + r_max * r_max) / 4.0;
  return static_cast<int>(std::lround(region.area_or_volume() * (1 - porosity) / per_particle));
}

double porosity_2d_from_3d(double n3d) {
  const double spheres_min = 0.2595, spheres_max = 0.4764, disks_min = 0.0931, disks_max = 0.2146;
  const double relative_density = (spheres_max - n3d) / (spheres_max - spheres_min);
  return disks_max - relative_density * (disks_max - disks_min);
}

OverlapStats overlap_stats(const Region& region, const std::vector<PackedParticle>& particles) {
  return region.dimension == 2 ? stats_of<2>(region, particles) : stats_of<3>(region, particles);
}

}  // namespace talus::dem
