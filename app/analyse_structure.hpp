#pragma once
// talus analyse contacts | rdf | d2min | packing: the structure of the grains in any DEM run's
// particle snapshots (Götz 2024 §5.3: contact number, radial distribution function,
// non-affine displacement D^2_min, local Voronoi packing fraction). Results go to <out>
// (default <run>/analysis); bad input throws InputError before anything is written.
#include <limits>
#include <string>

namespace talus::app {

// Shared by the four commands. Times pick the nearest snapshot; a time more than half a
// snapshot interval before the first or after the last snapshot is refused.
struct StructureOptions {
  std::string run_dir, out;
  bool quiet = false;
};

struct ContactsOptions : StructureOptions {
  double from = 0.0;                                    // first snapshot at or after
  double to = std::numeric_limits<double>::infinity();  // last snapshot at or before
  double gap = 0.0;       // grains closer than this (surface to surface, m) touch
  int min_contacts = -1;  // rattler threshold (< 0: D + 1)
};

struct RdfCommandOptions : StructureOptions {
  double time = std::numeric_limits<double>::quiet_NaN();   // NaN: the last snapshot
  double r_max = std::numeric_limits<double>::quiet_NaN();  // NaN: 5 mean diameters
  int bins = 100;
};

struct D2minCommandOptions : StructureOptions {
  double from = std::numeric_limits<double>::quiet_NaN();  // reference; NaN: the first snapshot
  double to = std::numeric_limits<double>::quiet_NaN();    // NaN: the last snapshot
  // Neighbourhood radius at the reference time; NaN: 2.5 mean diameters (Falk & Langer's 2.5
  // particle sizes).
  double cutoff = std::numeric_limits<double>::quiet_NaN();
  double gap = 0.0;      // contact definition for min_contacts
  int min_contacts = 0;  // leave out grains with fewer contacts at the reference time
  // Spatial autocorrelation C(r) of D_min (Götz eq. 48-49) in bins of this width, m; NaN: not
  // computed.
  double correlation = std::numeric_limits<double>::quiet_NaN();
  // Its largest distance, m; NaN: 5 mean diameters (the default range of rdf).
  double correlation_rmax = std::numeric_limits<double>::quiet_NaN();
};

struct PackingOptions : StructureOptions {
  double time = std::numeric_limits<double>::quiet_NaN();  // NaN: the last snapshot
  double margin = 0.0;  // also leave out grains closer than this to the box (m)
};

// contacts.csv: time, grains, contacts, z, rattlers, z_no_rattlers, z_snapshot per snapshot.
int contacts_command(const ContactsOptions& options);
// rdf.csv (r, g, coordination) and rdf.json.
int rdf_command(const RdfCommandOptions& options);
// d2min.csv (per grain), d2min.pvd + d2min_000000.vtu (grains at the later time with the
// values as point data) and d2min.json (means); with a correlation bin width also
// d2min_correlation.csv (r, C, C_over_C0, grains, pairs).
int d2min_command(const D2minCommandOptions& options);
// packing.csv (per grain) and packing.json (means).
int packing_command(const PackingOptions& options);

}  // namespace talus::app
