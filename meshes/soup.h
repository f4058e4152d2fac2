// The polygon soup that mesh files are read into and that repair turns into a MeshData:
// CGAL's types, shared by the two translation units that include CGAL (mesh_files.cpp
// reads formats, soup_repair.cpp repairs soups). Private to meshes/: no other header
// includes CGAL.
#pragma once

#include "mesh_error.h"
#include "mesh_file_check.h"

#include "memory/huge_page_allocator.h"
#include "primitives/mesh_data.h"
#include "primitives/value_limits.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <fmt/format.h>
#include <boost/container/small_vector.hpp>

#include <cstdint>
#include <vector>

namespace lucent::soup {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// Containers handed to CGAL's readers. The checks have bounded every count already; these
// refuse to grow past the limits anyway (ASCII STL has no count to check up front).
enum class Cap { Vertices, Faces, Corners };

template <class Base, Cap C>
class Capped : public Base {
 public:
  using T = typename Base::value_type;
  using Base::Base;
  void push_back(const T& value) {
    grow(this->size() + 1);
    Base::push_back(value);
  }
  template <class... Args>
  T& emplace_back(Args&&... args) {
    grow(this->size() + 1);
    return Base::emplace_back(std::forward<Args>(args)...);
  }
  void resize(std::size_t n) {
    grow(n);
    Base::resize(n);
  }

 private:
  static void grow(std::size_t n) {
    if (C == Cap::Vertices && n > kMaxMeshVertices)
      throw MeshError(fmt::format("more than {} vertices", kMaxMeshVertices));
    if (C == Cap::Faces && n > kMaxMeshFaces)
      throw MeshError(fmt::format("more than {} faces", kMaxMeshFaces));
    if (C == Cap::Corners && n > kMaxFaceVertices)
      throw MeshError(fmt::format("a face with more than {} vertices", kMaxFaceVertices));
  }
};

// A polygon's corners, held in place up to a quad: a million-triangle mesh would otherwise
// make a million small heap blocks, a noticeable part of its load time
// (docs/performance-history.md). Capped, as CGAL's readers fill it.
using Polygon = Capped<boost::container::small_vector<std::size_t, 4>, Cap::Corners>;

// The polygons in huge pages when large (huge_page_allocator.h): those of a large mesh
// are tens of MB of fresh memory. (The points cannot be: CGAL's repair swaps them with a
// std::vector of its own.)
struct Soup {
  std::vector<Point> points;
  HugeVector<Polygon> polygons;
};

// Normals and texture coordinates of the input, per corner of each input polygon.
struct CornerAttributes {
  std::vector<Vec3> normals;              // empty: none
  std::vector<Vec2> uvs;                  // empty: none
  std::vector<std::size_t> polygonStart;  // corners of polygon p start at polygonStart[p]
  std::vector<int32_t> normalOf, uvOf;    // per corner, index into normals / uvs

  bool any() const { return !normals.empty() || !uvs.empty(); }
};

// The checks every soup passes before repair, whatever it was read from.
// CGAL's repair sorts points (NaN would break the order) and indexes with what it is given.
void checkSoup(const Soup& soup, const char* vertex, const char* vertices, const char* face);

// The repair pipeline (repair and orient the soup, Surface_mesh, triangulation, a second
// soup) peaks at roughly this many bytes per input point and per polygon corner, a little
// above the measured peak (docs/performance-history.md). A mesh that cannot fit is refused
// before the pipeline starts, rather than swapping for hours or being killed half way.
inline constexpr std::uintmax_t kPipelineBytesPerPoint = 250;
inline constexpr std::uintmax_t kPipelineBytesPerCorner = 170;

void checkMemory(const Soup& soup);

// The closed, outward-oriented (or open) triangle mesh of `soup`, with the attributes of
// the corners each triangle came from (soup_repair.cpp).
MeshData repairSoup(Soup soup, const CornerAttributes& attrs);

// Runs `work`, turning the failures CGAL or the allocator can raise into MeshError.
template <class Work>
auto guarded(Work&& work) {
  try {
    return work();
  } catch (const MeshError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw MeshError("not enough memory for this mesh");
  } catch (const CGAL::Failure_exception& e) {
    throw MeshError(fmt::format("CGAL failed on this mesh: {}", e.message()));
  } catch (const std::exception& e) {
    throw MeshError(fmt::format("reading the mesh failed: {}", e.what()));
  }
}

}  // namespace lucent::soup
