// Test support: an independent checker of face partitions into topological
// disks.
//
// This file is deliberately independent of the Disk_segmentation library: it
// must not include any <CGAL/Disk_segmentation/...> header.
//
// Method. Every face is read as the cycle of its vertex indices (vertex
// index = position in the iteration order of vertices(tm)). For a set of faces
// ("patch"):
//   * edges are keyed by sorted vertex-index pairs in a std::map that records
//     the patch faces containing each edge; an edge with two patch faces is
//     interior to the patch, an edge with one is a boundary edge;
//   (a) connectivity: union-find over the patch faces, joined across interior
//       edges; there must be one class;
//   (b) no pinched vertex: union-find over the face corners (one element per
//       (face, vertex) incidence, i.e. one union-find per vertex over its
//       incident patch faces); for each interior edge (a, b) with faces f, g,
//       the corners of a in f and g are joined, and so are those of b. Each
//       vertex must end with all its corners in one class (one fan);
//   (c) Euler characteristic V - E + F == 1, V and E counting the distinct
//       vertices and edges of the patch faces;
//   (d) boundary edges are grouped into loops with a union-find joined at
//       shared vertices (each vertex must have 0 or 2 boundary edges); there
//       must be exactly one loop.
// For an orientable manifold patch, (a)+(b) make it a connected surface, and
// (c) or (d) then force genus 0 with one boundary component, i.e. a disk.

#ifndef DISK_SEGMENTATION_TEST_SUPPORT_INDEPENDENT_TOPOLOGY_H
#define DISK_SEGMENTATION_TEST_SUPPORT_INDEPENDENT_TOPOLOGY_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace test_support {

struct Partition_report
{
  bool ok;                       // true iff the partition is valid
  std::string problem;           // empty if ok, else a description of the first problem found
  std::size_t number_of_patches; // number of distinct patch ids seen
};

namespace topo_detail {

class Union_find
{
public:
  explicit Union_find(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }

  std::size_t find(std::size_t x)
  {
    while(parent_[x] != x)
    {
      parent_[x] = parent_[parent_[x]]; // path halving
      x = parent_[x];
    }
    return x;
  }

  void unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a != b)
      parent_[std::max(a, b)] = std::min(a, b);
  }

  std::size_t number_of_classes()
  {
    std::size_t n = 0;
    for(std::size_t i = 0; i < parent_.size(); ++i)
      if(find(i) == i)
        ++n;
    return n;
  }

private:
  std::vector<std::size_t> parent_;
};

typedef std::pair<std::size_t, std::size_t> Edge_key; // (smaller index, larger index)

inline Edge_key edge_key(std::size_t a, std::size_t b) { return a < b ? Edge_key(a, b) : Edge_key(b, a); }

typedef std::vector<std::size_t> Cycle; // vertex indices of one face, in order

// Numbers the vertices of tm by their position in vertices(tm).
template <class Mesh>
std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> vertex_indices(const Mesh& tm)
{
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> index;
  for(auto v : vertices(tm))
    index.emplace(v, index.size());
  return index;
}

template <class Mesh>
Cycle face_cycle(const Mesh& tm, typename boost::graph_traits<Mesh>::face_descriptor f,
                 const std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t>& index)
{
  Cycle c;
  for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
    c.push_back(index.at(v));
  return c;
}

// Reads the distinct faces of `faces` (in range order, duplicates dropped) as
// vertex-index cycles.
template <class Mesh, class FaceRange>
std::vector<Cycle> cycles_of(const Mesh& tm, const FaceRange& faces)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  const auto index = vertex_indices(tm);
  std::set<face_descriptor> seen;
  std::vector<Cycle> cycles;
  for(face_descriptor f : faces)
    if(seen.insert(f).second)
      cycles.push_back(face_cycle(tm, f, index));
  return cycles;
}

inline long euler_characteristic(const std::vector<Cycle>& faces)
{
  std::set<std::size_t> vs;
  std::set<Edge_key> es;
  for(const Cycle& c : faces)
    for(std::size_t i = 0; i < c.size(); ++i)
    {
      vs.insert(c[i]);
      es.insert(edge_key(c[i], c[(i + 1) % c.size()]));
    }
  return long(vs.size()) - long(es.size()) + long(faces.size());
}

// Checks (a)-(d) for the patch made of `faces`. labels[i] is the name of
// faces[i] used in messages (e.g. its index in the mesh). Returns true if the
// patch is a disk; otherwise sets `problem`.
inline bool check_disk(const std::vector<Cycle>& faces, const std::vector<std::size_t>& labels, std::string& problem)
{
  const std::size_t F = faces.size();
  if(F == 0)
  {
    problem = "empty patch";
    return false;
  }

  // Faces must be proper polygons.
  for(std::size_t f = 0; f < F; ++f)
  {
    std::set<std::size_t> distinct(faces[f].begin(), faces[f].end());
    if(faces[f].size() < 3 || distinct.size() != faces[f].size())
    {
      problem = "face " + std::to_string(labels[f]) + " has fewer than 3 vertices or a repeated vertex";
      return false;
    }
  }

  // Corner slots: corner k of face f is slot first_slot[f] + k.
  std::vector<std::size_t> first_slot(F + 1, 0);
  for(std::size_t f = 0; f < F; ++f)
    first_slot[f + 1] = first_slot[f] + faces[f].size();
  auto slot = [&](std::size_t f, std::size_t v) -> std::size_t {
    const Cycle& c = faces[f];
    return first_slot[f] + std::size_t(std::find(c.begin(), c.end(), v) - c.begin());
  };

  // Edge -> patch faces containing it; vertex -> its corner slots.
  std::map<Edge_key, std::vector<std::size_t> > edge_faces;
  std::map<std::size_t, std::vector<std::size_t> > vertex_slots;
  for(std::size_t f = 0; f < F; ++f)
  {
    const Cycle& c = faces[f];
    for(std::size_t k = 0; k < c.size(); ++k)
    {
      edge_faces[edge_key(c[k], c[(k + 1) % c.size()])].push_back(f);
      vertex_slots[c[k]].push_back(first_slot[f] + k);
    }
  }
  for(const auto& ef : edge_faces)
    if(ef.second.size() > 2)
    {
      problem = "edge (" + std::to_string(ef.first.first) + ", " + std::to_string(ef.first.second) +
                ") is shared by more than two faces";
      return false;
    }

  // (a) edge-connectivity
  Union_find face_classes(F);
  for(const auto& ef : edge_faces)
    if(ef.second.size() == 2)
      face_classes.unite(ef.second[0], ef.second[1]);
  const std::size_t components = face_classes.number_of_classes();
  if(components != 1)
  {
    problem = "not edge-connected (" + std::to_string(components) + " components)";
    return false;
  }

  // (b) one fan per vertex
  Union_find corner_classes(first_slot[F]);
  for(const auto& ef : edge_faces)
    if(ef.second.size() == 2)
    {
      const std::size_t f = ef.second[0], g = ef.second[1];
      corner_classes.unite(slot(f, ef.first.first), slot(g, ef.first.first));
      corner_classes.unite(slot(f, ef.first.second), slot(g, ef.first.second));
    }
  for(const auto& vs : vertex_slots)
  {
    std::set<std::size_t> fans;
    for(std::size_t s : vs.second)
      fans.insert(corner_classes.find(s));
    if(fans.size() != 1)
    {
      problem = "pinched vertex " + std::to_string(vs.first) + " (" + std::to_string(fans.size()) +
                " fans of patch faces around it)";
      return false;
    }
  }

  // (c) Euler characteristic
  const long V = long(vertex_slots.size()), E = long(edge_faces.size());
  const long chi = V - E + long(F);
  if(chi != 1)
  {
    problem = "Euler characteristic V - E + F = " + std::to_string(V) + " - " + std::to_string(E) + " + " +
              std::to_string(F) + " = " + std::to_string(chi) + " instead of 1";
    return false;
  }

  // (d) boundary loops
  std::vector<Edge_key> boundary;
  for(const auto& ef : edge_faces)
    if(ef.second.size() == 1)
      boundary.push_back(ef.first);
  std::map<std::size_t, std::vector<std::size_t> > vertex_boundary_edges;
  for(std::size_t e = 0; e < boundary.size(); ++e)
  {
    vertex_boundary_edges[boundary[e].first].push_back(e);
    vertex_boundary_edges[boundary[e].second].push_back(e);
  }
  Union_find loops(boundary.size());
  for(const auto& vb : vertex_boundary_edges)
  {
    if(vb.second.size() != 2)
    {
      problem = "vertex " + std::to_string(vb.first) + " has " + std::to_string(vb.second.size()) +
                " boundary edges instead of 2";
      return false;
    }
    loops.unite(vb.second[0], vb.second[1]);
  }
  const std::size_t n_loops = loops.number_of_classes();
  if(n_loops != 1)
  {
    problem = std::to_string(n_loops) + " boundary loops instead of 1";
    return false;
  }
  return true;
}

} // namespace topo_detail

// V - E + F of the distinct faces in `faces` (face descriptors of tm), V and E
// being the distinct vertices and edges of these faces.
template <class Mesh, class FaceRange>
long euler_characteristic_of(const Mesh& tm, const FaceRange& faces)
{
  return topo_detail::euler_characteristic(topo_detail::cycles_of(tm, faces));
}

// True iff the distinct faces of `faces` form a topological disk: (a)-(d).
template <class Mesh, class FaceRange>
bool is_disk(const Mesh& tm, const FaceRange& faces)
{
  const std::vector<topo_detail::Cycle> cycles = topo_detail::cycles_of(tm, faces);
  std::vector<std::size_t> labels(cycles.size());
  std::iota(labels.begin(), labels.end(), std::size_t(0));
  std::string problem;
  return topo_detail::check_disk(cycles, labels, problem);
}

// Checks that `patch_ids` (readable property map: face_descriptor ->
// std::size_t) is a partition of faces(tm) into topological disks whose ids
// are exactly 0..P-1. A face whose id is std::size_t(-1) counts as having no
// id. Face indices in messages are positions in faces(tm), vertex indices are
// positions in vertices(tm).
template <class Mesh, class PatchMap>
Partition_report check_disk_partition(const Mesh& tm, PatchMap patch_ids)
{
  Partition_report report{false, std::string(), 0};
  const auto index = topo_detail::vertex_indices(tm);

  std::vector<topo_detail::Cycle> cycles;
  std::map<std::size_t, std::vector<std::size_t> > members; // patch id -> face indices
  std::size_t fi = 0;
  for(auto f : faces(tm))
  {
    cycles.push_back(topo_detail::face_cycle(tm, f, index));
    const std::size_t id = static_cast<std::size_t>(get(patch_ids, f));
    if(id == std::size_t(-1))
    {
      report.problem = "face " + std::to_string(fi) + " has no patch id";
      return report;
    }
    members[id].push_back(fi);
    ++fi;
  }
  report.number_of_patches = members.size();

  // ids must be exactly 0..P-1: they are sorted in the map, so id k must be
  // the k-th key.
  std::size_t expected = 0;
  for(const auto& m : members)
  {
    if(m.first != expected)
    {
      report.problem = "patch ids are not contiguous: id " + std::to_string(expected) + " is missing (" +
                       std::to_string(members.size()) + " distinct ids, largest " +
                       std::to_string(members.rbegin()->first) + ")";
      return report;
    }
    ++expected;
  }

  for(const auto& m : members)
  {
    std::vector<topo_detail::Cycle> patch;
    for(std::size_t f : m.second)
      patch.push_back(cycles[f]);
    std::string problem;
    if(!topo_detail::check_disk(patch, m.second, problem))
    {
      report.problem = "patch " + std::to_string(m.first) + " (" + std::to_string(m.second.size()) +
                       " faces) is not a disk: " + problem;
      return report;
    }
  }
  report.ok = true;
  return report;
}

// The patches as sets of face indices (positions in faces(tm)); each set is
// sorted increasingly and the sets are sorted lexicographically, so the result
// does not depend on how the patches are numbered.
template <class Mesh, class PatchMap>
std::vector<std::vector<std::size_t> > patches_as_face_index_sets(const Mesh& tm, PatchMap patch_ids)
{
  std::map<std::size_t, std::vector<std::size_t> > members;
  std::size_t fi = 0;
  for(auto f : faces(tm))
    members[static_cast<std::size_t>(get(patch_ids, f))].push_back(fi++);
  std::vector<std::vector<std::size_t> > result;
  for(auto& m : members)
    result.push_back(std::move(m.second)); // already increasing
  std::sort(result.begin(), result.end());
  return result;
}

// True iff every patch of `fine` lies inside a single patch of `coarse`
// (every face of a fine patch must appear in coarse, all in the same patch).
inline bool refines(const std::vector<std::vector<std::size_t> >& fine,
                    const std::vector<std::vector<std::size_t> >& coarse)
{
  std::map<std::size_t, std::size_t> coarse_patch_of; // face index -> coarse patch position
  for(std::size_t p = 0; p < coarse.size(); ++p)
    for(std::size_t f : coarse[p])
      coarse_patch_of[f] = p;
  for(const std::vector<std::size_t>& patch : fine)
  {
    std::set<std::size_t> containers;
    for(std::size_t f : patch)
    {
      auto it = coarse_patch_of.find(f);
      if(it == coarse_patch_of.end())
        return false;
      containers.insert(it->second);
    }
    if(containers.size() > 1)
      return false;
  }
  return true;
}

} // namespace test_support

#endif // DISK_SEGMENTATION_TEST_SUPPORT_INDEPENDENT_TOPOLOGY_H
