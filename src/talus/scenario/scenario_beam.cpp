// [beam]: the granular beam's 3-point bending protocol (Götz 2024 §5.2,
// spec/membranes-and-jamming.md; dem::BeamParams), checked against the
// membranes, run and output already read; and its table for the resolved
// scenario (the given keys only).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

const dem::MembraneSpec& beam_membrane(TomlReader& r, const dem::DemScenario& s,
                                       const std::string& name) {
  auto m = std::find_if(s.membranes.begin(), s.membranes.end(),
                        [&](const dem::MembraneSpec& x) { return x.name == name; });
  if (m == s.membranes.end()) r.fail("membrane", fmt::format("no membrane named '{}'", name));
  // The rig finds its faces on an axis-aligned box lying along x, free until
  // the supports are pinned, compacted by its own vacuum.
  if (m->mesh != dem::MembraneMeshKind::Box || m->fixed != dem::MembraneFixed::None ||
      !(m->pressure < 0) || !(m->size_x > m->size_y && m->size_x > m->size_z))
    r.fail("membrane", fmt::format("membrane '{}' must be a \"box\" longest along x, with no fixed "
                                   "particles and a vacuum (pressure < 0)",
                                   name));
  return *m;
}

const EnumNames<dem::BeamTest> kBeamTests = {{"three_point", dem::BeamTest::ThreePoint},
                                             {"four_point", dem::BeamTest::FourPoint}};

// The load steps of the three-point test.
void read_load_steps(TomlReader& r, const dem::DemScenario& s, dem::BeamParams& b) {
  r.reject({"rod_speed", "rod_ramp", "max_strain", "bending_friction", "yield_smoothing"},
           "not used by test = \"three_point\"");
  b.max_load = required_number_in(r, "max_load", positive());
  b.load_step = required_number_in(r, "load_step", positive());
  const double n = b.max_load / b.load_step;
  r.expect(std::abs(n - std::round(n)) < 1e-9 * n && std::round(n) <= 100, "load_step",
           fmt::format("a whole fraction of max_load ({} N), at most 100 steps", b.max_load));
  b.load_steps = static_cast<int>(std::round(n));
  b.step_time = required_number_in(r, "step_time", positive());
  b.load_ramp =
      number_in(r, "load_ramp", 0.25 * b.step_time, between(0.0, b.step_time, false, true));
  // The source fits E_b with eq. 36 (spec) and does not give ν_b.
  b.beam_poisson_ratio =
      required_number_in(r, "beam_poisson_ratio", between(-1.0, 0.5, true, true));
  if (s.run.duration < b.end() - 1e-12)
    r.fail("step_time",
           fmt::format("no time for the load steps: 2 x {} + 1 steps of {} s from {} s end at "
                       "{:.6g} s, but run.duration is {} s",
                       b.load_steps, b.step_time, b.bending_start, b.end(), s.run.duration));
}

// The rods of the four-point test (Götz 2024 §5.3).
void read_rods(TomlReader& r, const dem::DemScenario& s, const dem::MembraneSpec& mem,
               dem::BeamParams& b) {
  r.reject({"max_load", "load_step", "step_time", "load_ramp", "beam_poisson_ratio"},
           "not used by test = \"four_point\"");
  b.rod_speed = required_number_in(r, "rod_speed", positive());
  b.max_strain = required_number_in(r, "max_strain", between(0.0, 0.5, false, true));
  // eq. 44 solved for Δz with the rest length and height; the span between
  // the supports is shorter by a support length, which the observer measures.
  b.rod_travel = b.max_strain * 23.0 * mem.size_x * mem.size_x / (108.0 * mem.size_z);
  b.rod_ramp = number_in(r, "rod_ramp", 0.0, non_negative());
  b.yield_smoothing = number_in(r, "yield_smoothing", b.max_strain / 40.0,
                                between(0.0, b.max_strain / 5.0, false, true));
  r.expect(0.5 * b.rod_speed * b.rod_ramp <= b.rod_travel, "rod_ramp",
           fmt::format("a ramp that ends before the rods' travel of {:.4g} m does", b.rod_travel));
  b.bending_friction = optional_number_in(r, "bending_friction", non_negative());
  if (b.bending_friction && s.sources.empty())
    r.fail("bending_friction", "no [[particles]] whose material it could change");
  if (s.run.duration < b.end() - 1e-12)
    r.fail("rod_speed",
           fmt::format("no time for the rods' travel of {:.4g} m (max_strain {}): from {} s it "
                       "ends at {:.6g} s, but run.duration is {} s",
                       b.rod_travel, b.max_strain, b.bending_start, b.end(), s.run.duration));
}

}  // namespace

void read_beam(TomlReader& r, dem::DemScenario& s) {
  dem::BeamParams b;
  b.test = r.enumeration("test", kBeamTests, dem::BeamTest::ThreePoint);
  b.membrane = r.required_string("membrane");
  const auto& mem = beam_membrane(r, s, b.membrane);
  b.mould_end = required_number_in(r, "mould_end", non_negative());
  r.expect(b.mould_end >= mem.pressure_ramp_end, "mould_end",
           fmt::format("a time no earlier than the end of the membrane's pressure_ramp ({} s): "
                       "the mould holds the beam while the vacuum rises",
                       mem.pressure_ramp_end));
  b.bending_start = required_number_in(r, "bending_start", non_negative());
  r.expect(b.bending_start >= b.mould_end, "bending_start",
           fmt::format("a time no earlier than 'mould_end' ({} s)", b.mould_end));
  const double half_flat_x = 0.5 * mem.size_x - mem.edge_radius;
  b.support_length = required_number_in(r, "support_length", positive());
  r.expect(b.support_length > mem.edge_radius && b.support_length < 0.5 * mem.size_x,
           "support_length",
           fmt::format("a length between the edge radius ({} m: the flat bottom starts there) "
                       "and half the beam ({} m)",
                       mem.edge_radius, 0.5 * mem.size_x));
  b.load_length = required_number_in(r, "load_length", positive());
  r.expect(b.load_length < 2 * half_flat_x, "load_length",
           fmt::format("a length within the flat top ({} m)", 2 * half_flat_x));
  b.measure_length = required_number_in(r, "measure_length", positive());
  r.expect(b.measure_length < 2 * half_flat_x, "measure_length",
           fmt::format("a length within the flat bottom ({} m)", 2 * half_flat_x));
  b.damping = number_in(r, "damping", 0.0, non_negative());
  b.damping_end = number_in(r, "damping_end", dem::kNever, non_negative());
  r.expect(b.damping_end > b.mould_end, "damping_end",
           fmt::format("a time after 'mould_end' ({} s), when the damping starts", b.mould_end));
  if (b.test == dem::BeamTest::ThreePoint)
    read_load_steps(r, s, b);
  else
    read_rods(r, s, mem, b);
  if (s.output.checkpoint_interval > 0)
    r.fail("membrane",
           "checkpoints of [beam] runs are not supported (the mould and the pinned supports are "
           "not stored): leave output.checkpoint_interval out");
  r.finish();
  s.beam = b;
}

nlohmann::ordered_json beam_table(const dem::BeamParams& b) {
  nlohmann::ordered_json t = {{"test", name_of(kBeamTests, b.test)},
                              {"membrane", b.membrane},
                              {"mould_end", b.mould_end},
                              {"bending_start", b.bending_start},
                              {"support_length", b.support_length},
                              {"load_length", b.load_length},
                              {"measure_length", b.measure_length},
                              {"damping", b.damping}};
  if (std::isfinite(b.damping_end)) t["damping_end"] = b.damping_end;
  if (b.test == dem::BeamTest::ThreePoint) {
    t["max_load"] = b.max_load;
    t["load_step"] = b.load_step;
    t["step_time"] = b.step_time;
    t["load_ramp"] = b.load_ramp;
    t["beam_poisson_ratio"] = b.beam_poisson_ratio;
  } else {
    t["rod_speed"] = b.rod_speed;
    t["rod_ramp"] = b.rod_ramp;
    t["max_strain"] = b.max_strain;
    t["yield_smoothing"] = b.yield_smoothing;
    if (b.bending_friction) t["bending_friction"] = *b.bending_friction;
  }
  return t;
}

}  // namespace talus::io::detail
