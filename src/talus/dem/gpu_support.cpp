#include "talus/dem/gpu_support.hpp"

#include "talus/dem/contact/hertz_mindlin.hpp"
#include "talus/dem/contact/linear.hpp"

namespace talus::dem {

std::vector<std::string> gpu_missing_features(const DemScenario& sc) {
  std::vector<std::string> out;
  if (sc.contact.model != HertzMindlin::name && sc.contact.model != LinearSpringDashpot::name)
    out.push_back("[contact] model = \"" + sc.contact.model +
                  "\" (the GPU backend has hertz_mindlin and linear)");
  if (sc.contact.rolling == RollingModel::Kuen)
    out.push_back("[contact] rolling = \"kuen\" (the GPU backend has none and epsd)");
  if (!sc.membranes.empty()) out.push_back("[[membranes]]");
  if (sc.triaxial) out.push_back("the [triaxial] experiment");
  if (sc.hollow_sphere) out.push_back("the [hollow_sphere] experiment");
  if (sc.gripper) out.push_back("the [gripper] experiment");
  if (sc.beam) out.push_back("the [beam] experiment");
  for (const auto& w : sc.walls) {
    if (w.kind == WallKind::Triangle || w.kind == WallKind::Mesh)
      out.push_back("triangle or mesh wall '" + w.name + "' (the GPU backend has planes, " +
                    "segments, arcs and cylinders)");
    if (w.motion.servo_pressure != 0.0)
      out.push_back("stress-controlled (servo) wall '" + w.name + "'");
  }
  return out;
}

std::string gpu_refusal(const DemScenario& sc, const std::vector<std::string>& missing) {
  std::string msg = "scenario '" + sc.name + "' uses what the GPU backend does not have:";
  for (const auto& m : missing) msg += "\n  - " + m;
  msg += "\nrun it with --backend cpu";
  return msg;
}

}  // namespace talus::dem
