#pragma once
// Grain-membrane contacts (spec/membranes-and-jamming.md, Götz 2024 §3.2.3):
// spheres against the triangles of the current mesh. The closest point of each
// nearby triangle is classified as vertex, edge or face contact; with the
// priority face > edge > vertex of Hu et al. (2013) a vertex or edge contact
// is dropped when a triangle sharing that vertex or edge has a higher-priority
// contact, and a vertex or edge shared by several triangles gives one force.
// One addition (see select_contacts): it is also dropped when such a triangle
// has a closer contact, i.e. only local minima of the distance to the mesh
// count; the priority rule alone double-counts on flat sheets.
// The membrane velocity at the contact point is interpolated with the
// barycentric weights w_i, and the vertices get -w_i F_c (sum w_i = 1, so
// momentum is conserved to round-off).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "talus/dem/contact/hertz_mindlin.hpp"
#include "talus/dem/membrane/mesh.hpp"

namespace talus::dem::membrane {

// The law of every grain-membrane, membrane-membrane and sphere-membrane
// contact (Götz 2024: the viscoelastic Hertz law for walls and membranes
// alike). The scenario reader requires [contact] model to name it.
using ContactLaw = ViscoelasticHertz;

// The value is the priority of Götz Table 1.
enum class Feature : uint8_t { Vertex = 1, Edge = 2, Face = 3 };

// Closest point of the triangle (a, b, c) to x (Ericson, Real-Time Collision
// Detection 5.1.5), with its region: `corner` is the vertex (Vertex) or the
// corner opposite the edge (Edge, as Mesh::triangle_edges), -1 for Face.
struct TrianglePoint {
  Vec3 point;
  std::array<double, 3> w;  // barycentric weights of point, sum 1
  Feature kind;
  int corner;
};
TrianglePoint closest_on_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x);

struct TriangleContact {
  int triangle = -1;
  Feature kind = Feature::Face;
  int feature = -1;  // mesh index of the vertex, edge or triangle touched
  Vec3 point = Vec3::Zero();
  std::array<double, 3> w{};  // weights of the triangle's corners
  double distance = 0;        // from the sphere centre to point
};

// Contacts of a sphere (centre, radius) with the candidate triangles of a mesh
// at positions x, after the priority rule; appended to out (cleared first).
// `scratch` holds the triangles touched before the rule: pass the same vector
// on every call, so that the contact path allocates only while it grows.
void select_contacts(const Mesh& mesh, std::span<const Vec3> x, const Vec3& centre, double radius,
                     std::span<const int> candidates, std::vector<TriangleContact>& out,
                     std::vector<TriangleContact>& scratch);
// The same with a scratch vector of its own (allocates; for one-off calls).
inline void select_contacts(const Mesh& mesh, std::span<const Vec3> x, const Vec3& centre,
                            double radius, std::span<const int> candidates,
                            std::vector<TriangleContact>& out) {
  std::vector<TriangleContact> scratch;
  select_contacts(mesh, x, centre, radius, candidates, out, scratch);
}

// Tangential springs of grain-membrane contacts, keyed by (grain, feature).
// When a contact moves onto another feature (face to face across an edge, say)
// its spring moves with it: a new key takes the spring of the same grain's
// contact of the previous step that has not continued and whose contact point
// was nearest, if it was within the grain radius. Without this, every crossing
// of a triangle boundary would reset friction (the oscillation at the mesh
// period that the triangle model is meant to remove).
//
// Lanes: grains may be handled by several threads at once, each grain by one
// lane in a step. springs() and store() of different lanes touch different
// data (a grain's previous entries, the lane's own buffers), so lanes may run
// concurrently; begin_step() joins the lanes in lane order, so the result does
// not depend on which thread ran which lane.
class ContactMemory {
 public:
  // Call once per step before the first contact: this step's springs become
  // the previous ones; `lanes` lanes are open for this step.
  void begin_step(int lanes = 1);
  // Springs of all contacts of one grain (exact key first, then transfers),
  // zero for new contacts, one per contact. They live in a buffer of the
  // lane, valid until its next call. Call once per grain and step, then
  // store() each updated spring in the same lane.
  std::span<ContactHistory<3>> springs(int64_t grain, std::span<const TriangleContact> contacts,
                                       double radius, int lane = 0);
  void store(int64_t grain, const TriangleContact& c, const ContactHistory<3>& h, int lane = 0);
  std::size_t size() const;

  // The springs stored since the last begin_step, for checkpoints: the lanes
  // joined in lane order, which is all the next begin_step reads.
  struct Saved {
    std::vector<int64_t> grain;
    std::vector<uint64_t> feature;
    std::vector<Vec3> point, shear, roll;
  };
  Saved saved() const;
  // Puts saved springs back as this step's, all in lane 0: the next
  // begin_step joins them in the same order as the lanes they came from.
  // Throws InputError when the arrays differ in length.
  void restore(const Saved& s);

 private:
  struct Entry {
    int64_t grain;
    uint64_t feature;  // kind << 32 | index
    Vec3 point;
    ContactHistory<3> history;
    bool continued;
  };
  struct Lane {
    std::vector<Entry> current;
    // Buffers of springs(), kept between calls so that they allocate only while they grow.
    std::vector<ContactHistory<3>> springs;
    std::vector<char> found;
  };
  std::vector<Entry> previous_;
  std::vector<Lane> lanes_ = std::vector<Lane>(1);
};

// A sphere as the contact sees it.
struct Grain {
  Vec3 x = Vec3::Zero(), v = Vec3::Zero(), w = Vec3::Zero();
  double radius = 0, mass = 0;
};

struct GrainForce {
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  int contacts = 0;
};

// Viscoelastic Hertz forces (dem/contact/hertz_mindlin.hpp, as walls: r_eff =
// R, m_eff = m of the grain, lever arm R - overlap/2) of the selected contacts
// on the grain; the reactions -w_i F go into f_mem. `contacts` comes from
// select_contacts for this grain and these positions.
GrainForce grain_membrane_forces(const Mesh& mesh, std::span<const Vec3> x_mem,
                                 std::span<const Vec3> v_mem, std::span<Vec3> f_mem,
                                 int64_t grain_id, const Grain& g,
                                 std::span<const TriangleContact> contacts,
                                 const ContactLaw::Coeffs& coeffs, double dt,
                                 ContactMemory& memory);
// The same for one lane of a multi-threaded pass: the reactions are appended
// to `reactions` as (vertex, force) for the caller to add in a fixed order.
GrainForce grain_membrane_forces(const Mesh& mesh, std::span<const Vec3> x_mem,
                                 std::span<const Vec3> v_mem,
                                 std::vector<std::pair<int, Vec3>>& reactions, int64_t grain_id,
                                 const Grain& g, std::span<const TriangleContact> contacts,
                                 const ContactLaw::Coeffs& coeffs, double dt, ContactMemory& memory,
                                 int lane);

// A sphere of prescribed motion (driven_sphere.hpp) against the selected
// triangles: the grain-membrane law with m_eff the mass of the contact point
// alone, 1 / sum_k w_k^2 / m_k (the sphere does not yield, as if infinitely
// heavy). The reactions -w_k F go into f_mem; the force on the sphere is returned.
GrainForce rigid_sphere_forces(const Mesh& mesh, std::span<const Vec3> x_mem,
                               std::span<const Vec3> v_mem, std::span<const double> mass,
                               std::span<Vec3> f_mem, int64_t sphere_id, const Grain& g,
                               std::span<const TriangleContact> contacts,
                               const ContactLaw::Coeffs& coeffs, double dt, ContactMemory& memory);

// A particle of the membrane itself (self_contact.hpp) against the selected
// triangles: the same law, with the particle as a sphere of `radius` that does
// not rotate, and m_eff the reduced mass of the particle and the contact point
// (mass 1 / sum_k w_k^2 / m_k: the acceleration of the point under a force F
// there is F sum_k w_k^2 / m_k). The force goes to f[particle], the reactions
// -w_k F to the corners; springs in lane 0 of `memory`, keyed by particle.
// Returns the number of contacts.
int particle_triangle_forces(const Mesh& mesh, std::span<const Vec3> x, std::span<const Vec3> v,
                             std::span<const double> mass, std::span<Vec3> f, int particle,
                             double radius, std::span<const TriangleContact> contacts,
                             const ContactLaw::Coeffs& coeffs, double dt, ContactMemory& memory);

// Candidate triangles near spheres: a uniform grid of triangle bounding boxes,
// rebuilt whenever the membrane has moved (cheap: one pass over the triangles).
class TriangleGrid {
 public:
  // Marks of the triangles one query has seen; one per thread.
  struct Scratch {
    std::vector<int> stamp;
    int id = 0;
  };
  void build(const Mesh& mesh, std::span<const Vec3> x, double cell);
  // Triangles whose cells overlap the sphere's bounding box and whose
  // bounding sphere (centroid, farthest corner) meets the sphere, each once.
  void query(const Vec3& centre, double radius, std::vector<int>& out) const {
    query(centre, radius, out, scratch_);
  }
  // The same with the caller's scratch: queries with different scratches may
  // run concurrently.
  void query(const Vec3& centre, double radius, std::vector<int>& out, Scratch& scratch) const;

 private:
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 1;
  Eigen::Vector3i dims_ = Eigen::Vector3i::Ones();
  std::vector<int> start_, list_;
  std::vector<Vec3> centroid_;
  std::vector<double> bound_;  // distance from the centroid to the farthest corner
  mutable Scratch scratch_;
  Eigen::Vector3i cell_of(const Vec3& p) const;
};

}  // namespace talus::dem::membrane
