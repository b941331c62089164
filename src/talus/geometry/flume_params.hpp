#pragma once
// The flume as a scenario describes it, once for every method: DEM and MPM
// read it from [flume], DAN and fv2d from [path] type = "flume", and all four
// build their geometry from the same FlumeShape with geometry::make_flume.
#include <optional>
#include <string>

namespace talus::geometry {

// The Mancarella & Hungr flume's path (spec: flume.md): chute, arc, barrier.
// Unset lengths take Kuen's Table 2 values for (beta, arc_radius).
struct FlumeShape {
  double beta = 0.0;                     // barrier angle, rad
  double arc_radius = 0.10;              // m
  std::optional<double> l_star;          // chute top to corner, m
  std::optional<double> barrier_length;  // corner to barrier end, m
};

// How a particle or point run on the flume is measured (DEM and MPM).
struct FlumeMeasures {
  double front_quantile = 0.998;  // front = this quantile of the grains' path coordinate
  double profile_bin = 0.01;      // m of path per bin of the deposit profile
  double tail_thickness = 0.0;    // m; main deposit = thicker than this (0: 3 grain sizes)
};

// The DEM flume: [flume] generates the walls chute, arc, barrier, gate and
// lid (2D) and, with [flume.release], the fill behind the gate; a run with it
// reports the flume analysis (front along the path, deposit, run-up, forces).
struct FlumeParams {
  FlumeShape shape;
  std::string wall_material;
  bool lift_gate = false;    // false: the gate is deleted at gate_open (Kuen's variant I)
  double gate_speed = 2.25;  // m/s upwards when lifted (variant II)
  double gate_open = 0.0;    // s
  int layers = 5;            // horizontal bands of the settled mass, for colouring
  FlumeMeasures measures;
};

}  // namespace talus::geometry
