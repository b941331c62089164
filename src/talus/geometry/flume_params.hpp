#pragma once
// The flume as a scenario describes it, once for every method (DEM, MPM, DAN
// and fv2d build their geometry from it with geometry::make_flume).
#include <optional>
#include <string>

namespace talus::geometry {

// The Mancarella & Hungr flume (spec: flume.md) built from the barrier angle
// and arc radius: [flume] generates the walls chute, arc, barrier, gate and
// lid (2D) and, with [flume.release], the fill behind the gate; a run with it
// reports the flume analysis (front along the path, deposit, run-up, forces).
struct FlumeParams {
  double beta = 0.0;                     // barrier angle, rad
  double arc_radius = 0.10;              // m
  std::optional<double> l_star;          // chute top to corner, m (default: Kuen's Table 2)
  std::optional<double> barrier_length;  // corner to barrier end, m (default: Table 2)
  std::string wall_material;
  bool lift_gate = false;    // false: the gate is deleted at gate_open (Kuen's variant I)
  double gate_speed = 2.25;  // m/s upwards when lifted (variant II)
  double gate_open = 0.0;    // s
  // Analysis
  int layers = 5;                 // horizontal bands of the settled mass, for colouring
  double front_quantile = 0.998;  // front = this quantile of the particles' path coordinate
  double profile_bin = 0.01;      // m of path per bin of the deposit profile
  double tail_thickness = 0.0;    // m; main deposit = thicker than this (0: 3 mean diameters)
};

}  // namespace talus::geometry
