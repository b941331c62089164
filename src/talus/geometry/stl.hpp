#pragma once
// STL triangle meshes (ASCII and binary) for 3D walls.
#include <cstddef>
#include <string>
#include <vector>

#include "talus/geometry/primitive.hpp"

namespace talus::geometry {

// Reads an STL file into triangles, each vertex mapped to scale * v + offset.
// The format is detected from the content (a binary file may also begin with
// "solid"). Normals are recomputed from the vertex order; the stored normals are
// ignored, as most readers do, because exporters often leave them zero.
// Facets that span no area are dropped (counted in *degenerate if given).
// Throws InputError naming the file (and the line, for ASCII) on bad input.
std::vector<Primitive> read_stl(const std::string& path, double scale = 1.0,
                                const Vec3& offset = Vec3::Zero(),
                                std::size_t* degenerate = nullptr);

// Writes triangles (kind Triangle) as ASCII or binary STL, single precision
// for binary. Throws RunError when the file cannot be written.
void write_stl(const std::string& path, const std::vector<Primitive>& triangles, bool binary,
               const std::string& solid_name = "talus");

}  // namespace talus::geometry
