#include "talus/dem/membrane/beam_rig.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/dem/membrane/from_spec.hpp"
#include "talus/dem/system.hpp"

namespace talus::dem {

int BeamParams::step_at(double t) const {
  if (t < bending_start) return -1;
  return std::min(2 * load_steps + 1, static_cast<int>((t - bending_start) / step_time));
}

double BeamParams::load_at(double t) const {
  const int k = step_at(t);
  if (k <= 0 || k > 2 * load_steps) return 0.0;
  const double u = load_ramp > 0 ? (t - bending_start - k * step_time) / load_ramp : 1.0;
  return step_load(k - 1) + (step_load(k) - step_load(k - 1)) * std::clamp(u, 0.0, 1.0);
}

double BeamParams::rod_travel_at(double t) const {
  const double tau = t - bending_start;
  if (!(tau > 0)) return 0.0;
  const double ramped =
      tau < rod_ramp ? 0.5 * rod_speed * tau * tau / rod_ramp : rod_speed * (tau - 0.5 * rod_ramp);
  return std::min(ramped, rod_travel);
}

double BeamParams::end() const {
  if (test == BeamTest::ThreePoint) return bending_start + (2 * load_steps + 1) * step_time;
  // The travel ends past the ramp (the parser asks for that).
  return bending_start + rod_travel / rod_speed + 0.5 * rod_ramp;
}

}  // namespace talus::dem

namespace talus::dem::membrane {

void apply_beam(const BeamParams& b, const DemScenario& sc, DemSystem<3>& s) {
  auto [spec, body] = named_membrane(sc.membranes, s.membranes, b.membrane, "[beam]");
  const auto& x = body.body.x;
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (const Vec3& p : x) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  // The flat faces of the rounded box lie on its outer box up to round-off.
  const double tol = 1e-6 * (hi - lo).maxCoeff();
  const double cx = 0.5 * (lo.x() + hi.x());
  BeamRig rig;
  rig.params = b;
  rig.mould_lo = lo;
  rig.mould_hi = hi;
  const bool four = b.test == BeamTest::FourPoint;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const bool bottom = x[i].z() <= lo.z() + tol, top = x[i].z() >= hi.z() - tol;
    const double off = std::abs(x[i].x() - cx);
    const int id = static_cast<int>(i);
    if (bottom && off >= 0.5 * (hi.x() - lo.x()) - b.support_length) rig.supports.push_back(id);
    if (top && !four && off <= 0.5 * b.load_length) rig.loaded.push_back(id);
    if (bottom && off <= 0.5 * b.measure_length) rig.measured.push_back(id);
    if (x[i].y() <= lo.y() + tol) rig.faces[0].push_back(id);
    if (x[i].y() >= hi.y() - tol) rig.faces[1].push_back(id);
    if (bottom) rig.faces[2].push_back(id);
    if (top) rig.faces[3].push_back(id);
  }
  const double spacing = spec.spacing;  // clang before 16 cannot capture a structured binding
  auto need = [&](const std::vector<int>& set, const char* key, const char* face) {
    if (set.empty())
      throw InputError(
          fmt::format("[beam] '{}': no membrane particle of '{}' on its {} face "
                      "within it (membrane spacing {} m)",
                      key, b.membrane, face, spacing));
  };
  need(rig.supports, "support_length", "flat bottom");
  if (four) {
    // The rods sit at the thirds of the span between the supports' centroids.
    const double third = support_span(rig, x) / 6.0;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i].z() >= hi.z() - tol &&
          std::abs(std::abs(x[i].x() - cx) - third) <= 0.5 * b.load_length)
        rig.rods.push_back(static_cast<int>(i));
    need(rig.rods, "load_length", "flat top at the span's thirds");
  } else {
    need(rig.loaded, "load_length", "flat top");
  }
  need(rig.measured, "measure_length", "flat bottom");
  // Both ends must carry the beam, or it is a cantilever.
  const auto left =
      std::count_if(rig.supports.begin(), rig.supports.end(), [&](int i) { return x[i].x() < cx; });
  if (left == 0 || left == static_cast<std::ptrdiff_t>(rig.supports.size()))
    throw InputError("[beam] 'support_length': supports at one end only");
  body.rig = std::move(rig);
}

double support_span(const BeamRig& rig, std::span<const Vec3> x) {
  const double cx = 0.5 * (rig.mould_lo.x() + rig.mould_hi.x());
  double left = 0, right = 0;
  int nl = 0, nr = 0;
  for (int i : rig.supports) {
    if (x[i].x() < cx) {
      left += x[i].x();
      ++nl;
    } else {
      right += x[i].x();
      ++nr;
    }
  }
  return nl > 0 && nr > 0 ? right / nr - left / nl : 0.0;
}

void hold_in_mould(BeamRig& rig, Membrane& m, double t) {
  if (t >= rig.params.mould_end) return;
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    if (!m.fixed[i]) {
      for (int a = 0; a < 3; ++a) {
        if (m.x[i][a] > rig.mould_hi[a]) {
          m.x[i][a] = rig.mould_hi[a];
          m.v[i][a] = std::min(m.v[i][a], 0.0);
        } else if (m.x[i][a] < rig.mould_lo[a]) {
          m.x[i][a] = rig.mould_lo[a];
          m.v[i][a] = std::max(m.v[i][a], 0.0);
        }
      }
    }
    lo = lo.cwiseMin(m.x[i]);
    hi = hi.cwiseMax(m.x[i]);
  }
  rig.mould_lo = rig.mould_lo.cwiseMax(lo);
  rig.mould_hi = rig.mould_hi.cwiseMin(hi);
}

void pin_supports_if_due(BeamRig& rig, Membrane& m, double t) {
  if (rig.supported || t < rig.params.bending_start) return;
  rig.supported = true;
  for (int i : rig.supports) {
    m.fixed[i] = 1;
    m.v[i].setZero();
  }
  rig.rod_anchor.clear();
  for (int i : rig.rods) {
    m.fixed[i] = 1;
    m.v[i].setZero();
    rig.rod_anchor.push_back(m.x[i]);
  }
}

void move_rods(const BeamRig& rig, Membrane& m, double t) {
  if (!rig.supported || rig.rods.empty()) return;
  const BeamParams& b = rig.params;
  const double travel = b.rod_travel_at(t);
  const double tau = t - b.bending_start;
  const double speed = travel >= b.rod_travel ? 0.0
                       : tau < b.rod_ramp     ? b.rod_speed * tau / b.rod_ramp
                                              : b.rod_speed;
  for (std::size_t k = 0; k < rig.rods.size(); ++k) {
    const int i = rig.rods[k];
    m.x[i] = rig.rod_anchor[k] - Vec3(0, 0, travel);
    m.v[i] = Vec3(0, 0, -speed);
  }
}

double rods_push(const BeamRig& rig, const Membrane& m, const Vec3& g) {
  // The rod holds particle i with -(f_i + m_i g); its z part is the push down.
  double push = 0.0;
  for (int i : rig.rods) push += m.f[i].z() + m.mass[i] * g.z();
  return push;
}

double damping_factor(const BeamRig& rig, double t, double dt) {
  if (!(rig.params.damping > 0) || t < rig.params.mould_end || t >= rig.params.damping_end)
    return 1.0;
  return std::exp(-rig.params.damping * dt);
}

void add_load(const BeamRig& rig, Membrane& m, double t) {
  if (rig.params.test != BeamTest::ThreePoint) return;
  const double f = rig.params.load_at(t);
  if (f == 0.0) return;
  const double share = f / static_cast<double>(rig.loaded.size());
  for (int i : rig.loaded) m.f[i].z() -= share;
}

}  // namespace talus::dem::membrane
