// POV-Ray 3.7's mesh camera (render/mesh_camera.h): which face each film point takes under
// each distribution (POV-Ray's rows one pixel lower), the ray from its centroid along its
// normal, the offset and reverse, the mesh's and the camera's transforms (the direction as
// a normal), uv lookup with interpolated normals. Expected values are worked out by hand.
#include "camera_checks.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace lucent;
using namespace lucent::camtest;

namespace {

// A screen of w x h faces, one per pixel, row-major from the top: face k = r·w + c has its
// centroid at (c, −r, 0) + (1/3, 1/3, 0)·... (corners (c, −r), (c + 1, −r), (c, 1 − r)),
// its normal (b − a) × (c − a) = +z.
std::shared_ptr<const MeshData> screen(int w, int h) {
  auto d = std::make_shared<MeshData>();
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const auto first = static_cast<uint32_t>(d->positions.size());
      d->positions.push_back(Vec3(c, -r, 0));
      d->positions.push_back(Vec3(c + 1, -r, 0));
      d->positions.push_back(Vec3(c, 1 - r, 0));
      d->triangles.push_back({first, first + 1, first + 2});
    }
  return d;
}

Vec3 centroid(int c, int r) { return Vec3(c + 1.0 / 3.0, -r + 1.0 / 3.0, 0.0); }

Camera meshCamera(int distribution, std::vector<Camera::FaceMesh> meshes, int rays = 1) {
  Camera cam;
  cam.type = CameraType::Mesh;
  cam.distribution = distribution;
  cam.raysPerPixel = rays;
  cam.meshes = std::move(meshes);
  return cam;
}

void checkVec(const Vec3& v, const Vec3& expected, double margin = 1e-12) {
  INFO("got " << v.x << " " << v.y << " " << v.z << ", expected " << expected.x << " " << expected.y
              << " " << expected.z);
  CHECK(v.x == Approx(expected.x).margin(margin));
  CHECK(v.y == Approx(expected.y).margin(margin));
  CHECK(v.z == Approx(expected.z).margin(margin));
}

Ray numbered(const Projection& p, const Vec2& film, int index) {
  Ray r;
  REQUIRE(p.generateRayNumber(film, Vec2(0.5), index, r));
  return r;
}

bool hasNumbered(const Projection& p, const Vec2& film, int index) {
  Ray r;
  return p.generateRayNumber(film, Vec2(0.5), index, r);
}

}  // namespace

TEST_CASE("mesh camera distribution 0: face row times width plus column one row lower",
          "[cameras][mesh-camera]") {
  const Camera cam = meshCamera(0, {{SourceLoc{}, screen(4, 3), Mat4(1.0)}});
  auto p = makeProjection(cam, 4, 3);
  CHECK(p->raysPerSample() == 1);
  CHECK_FALSE(p->fixedOrigin());
  // Pixel (2, 2)'s centre (2.5, 2.5) is POV-Ray's (2.5, 1.5): face 1·4 + 2.
  Ray r = rayAt(*p, Vec2(2.5, 2.5));
  checkVec(r.o, centroid(2, 1));
  checkVec(r.d, Vec3(0, 0, 1));
  // Rows 0 and 1 both take face row 0 (POV-Ray's y of row 0 is held at 0).
  checkVec(rayAt(*p, Vec2(1.5, 0.5)).o, centroid(1, 0));
  checkVec(rayAt(*p, Vec2(1.5, 1.5)).o, centroid(1, 0));
  // A screen of fewer faces than pixels: no ray past its last face.
  const Camera small = meshCamera(0, {{SourceLoc{}, screen(4, 1), Mat4(1.0)}});
  auto q = makeProjection(small, 4, 3);
  CHECK(hasRay(*q, Vec2(3.5, 1.5)));
  CHECK_FALSE(hasRay(*q, Vec2(0.5, 2.5)));
}

TEST_CASE("mesh camera: offset along the normal and reverse and the transforms",
          "[cameras][mesh-camera]") {
  // The mesh scaled by 2 along x and turned 90 degrees about y (x -> -z, z -> x): the face
  // normal +z, a normal, becomes +x; the camera moved up by 5.
  Camera cam = meshCamera(
      0, {{SourceLoc{}, screen(2, 2),
           glm::rotate(Mat4(1.0), kPi / 2, Vec3(0, 1, 0)) * glm::scale(Mat4(1.0), Vec3(2, 1, 1))}});
  cam.offset = 0.5;
  cam.transform = glm::translate(Mat4(1.0), Vec3(0, 5, 0));
  auto p = makeProjection(cam, 2, 2);
  Ray r = rayAt(*p, Vec2(1.5, 0.5));  // face 1: centroid (4/3, 1/3, 0), moved to z = 0.5
  // (x, y, z) scaled (2x, y, z) = (8/3, 1/3, 0.5), turned: (z, y, −x) = (0.5, 1/3, −8/3).
  checkVec(r.o, Vec3(0.5, 1.0 / 3.0 + 5.0, -8.0 / 3.0));
  checkVec(r.d, Vec3(1, 0, 0));
  cam.reverse = true;
  p = makeProjection(cam, 2, 2);
  r = rayAt(*p, Vec2(1.5, 0.5));
  checkVec(r.o, Vec3(0.5, 1.0 / 3.0 + 5.0, -8.0 / 3.0));  // moved before it is turned back
  checkVec(r.d, Vec3(-1, 0, 0));
  // A skew: the direction follows the inverse transpose, not the matrix.
  Camera skew = meshCamera(0, {{SourceLoc{}, screen(1, 1), Mat4(1.0)}});
  skew.meshes[0].transform = Mat4(1.0);
  skew.meshes[0].transform[2][0] = 1.0;  // x += z: the plane z = 0 stays put
  auto s = makeProjection(skew, 1, 1);
  // The normal of the sheared plane z = 0 is still +z (the matrix would give (1, 0, 1)).
  checkVec(rayAt(*s, Vec2(0.5, 0.5)).d, Vec3(0, 0, 1));
}

TEST_CASE("mesh camera distribution 0 with several meshes: ray r from mesh r averaged",
          "[cameras][mesh-camera]") {
  Camera cam = meshCamera(0,
                          {{SourceLoc{}, screen(2, 2), Mat4(1.0)},
                           {SourceLoc{}, screen(2, 2), glm::translate(Mat4(1.0), Vec3(0, 0, 7))}},
                          2);
  auto p = makeProjection(cam, 2, 2);
  CHECK(p->raysPerSample() == 2);
  checkVec(numbered(*p, Vec2(0.5, 0.5), 0).o, centroid(0, 0));
  checkVec(numbered(*p, Vec2(0.5, 0.5), 1).o, centroid(0, 0) + Vec3(0, 0, 7));
  CHECK_FALSE(hasNumbered(*p, Vec2(0.5, 0.5), 2));
}

TEST_CASE("mesh camera distribution 1: faces counted on across the meshes and ray 1 never",
          "[cameras][mesh-camera]") {
  // Two meshes of 2 faces each on a 2 x 2 image: face 2 (POV-Ray's row 1, column 0) is
  // the second mesh's first.
  Camera cam = meshCamera(1,
                          {{SourceLoc{}, screen(2, 1), Mat4(1.0)},
                           {SourceLoc{}, screen(2, 1), glm::translate(Mat4(1.0), Vec3(0, 0, 3))}},
                          2);
  auto p = makeProjection(cam, 2, 3);
  checkVec(rayAt(*p, Vec2(1.5, 0.5)).o, centroid(1, 0));
  checkVec(rayAt(*p, Vec2(0.5, 2.5)).o, centroid(0, 0) + Vec3(0, 0, 3));
  CHECK_FALSE(hasRay(*p, Vec2(0.5, 3.0)));  // face 4: past the last
  // POV-Ray 3.7 offsets ray r by r times the faces' count: past the last face.
  CHECK_FALSE(hasNumbered(*p, Vec2(0.5, 0.5), 1));
}

TEST_CASE("mesh camera distribution 2: meshes side by side with faces by the image's column",
          "[cameras][mesh-camera]") {
  Camera cam =
      meshCamera(2, {{SourceLoc{}, screen(2, 2), Mat4(1.0)},
                     {SourceLoc{}, screen(2, 2), glm::translate(Mat4(1.0), Vec3(0, 0, 4))}});
  auto p = makeProjection(cam, 4, 2);
  // Column 1 is the left mesh's face 1; column 3 the right mesh's face 0·2 + 3 = 3 (row 1,
  // column 1: POV-Ray does not take the mesh's own column).
  checkVec(rayAt(*p, Vec2(1.5, 0.5)).o, centroid(1, 0));
  checkVec(rayAt(*p, Vec2(3.5, 0.5)).o, centroid(1, 1) + Vec3(0, 0, 4));
  CHECK_FALSE(hasRay(*p, Vec2(3.5, 2.0)));  // row 1: face 1·2 + 3 = 5 of 4
}

TEST_CASE("mesh camera distribution 3: the face whose uvs hold the pixel's and smooth normals",
          "[cameras][mesh-camera]") {
  // One triangle over the whole uv square's lower left half: corners (0,0,0), (2,0,0),
  // (0,2,0) with uvs (0,0), (1,0), (0,1) and normals +z, +x, +y.
  auto d = std::make_shared<MeshData>();
  d->positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  d->uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  d->normals = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  d->triangles = {{0, 1, 2}};
  Camera cam = meshCamera(3, {{SourceLoc{}, d, Mat4(1.0)}});
  auto p = makeProjection(cam, 10, 10);
  // Pixel (2, 8): POV-Ray's (2.5, 7.5): u = 2/10, v = 1 − 8/10 = 0.2; weights (0.6, 0.2,
  // 0.2): the point (0.4, 0.4, 0), the face normal +z.
  Ray r = rayAt(*p, Vec2(2.5, 8.5));
  checkVec(r.o, Vec3(0.4, 0.4, 0.0));
  checkVec(r.d, Vec3(0, 0, 1));
  cam.smooth = true;
  p = makeProjection(cam, 10, 10);
  r = rayAt(*p, Vec2(2.5, 8.5));
  checkVec(r.d, glm::normalize(Vec3(0.2, 0.2, 0.6)));
  // The upper right half of the uv square holds no face: no ray.
  CHECK_FALSE(hasRay(*p, Vec2(8.5, 1.5)));
}

TEST_CASE("mesh camera distribution 3: of overlapping faces the first in order, at every pixel",
          "[cameras][mesh-camera]") {
  // A 6 x 5 grid of uv cells, each split into two triangles, under a second copy of the grid
  // shifted by a third of a cell (so faces overlap, and faces share edges where pixels may
  // fall), then degenerate faces. Each pixel's ray must come from the first face in order
  // whose uv triangle holds its (u, v), found here by scanning every face.
  auto d = std::make_shared<MeshData>();
  auto addGrid = [&](double shift) {
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 6; ++i) {
        const auto first = static_cast<uint32_t>(d->positions.size());
        for (auto [a, b] : {std::pair{0, 0}, {1, 0}, {0, 1}, {1, 1}}) {
          const Vec2 uv((i + a + shift) / 6.0, (j + b + shift) / 5.0);
          d->uvs.push_back(uv);
          d->positions.push_back(Vec3(uv * 3.0, 0.1 * d->positions.size()));
        }
        d->triangles.push_back({first, first + 1, first + 2});
        d->triangles.push_back({first + 1, first + 3, first + 2});
      }
  };
  addGrid(0.0);
  addGrid(1.0 / 3.0);
  d->triangles.push_back({0, 0, 1});
  const Camera cam = meshCamera(3, {{SourceLoc{}, d, Mat4(1.0)}});
  const int w = 24, h = 20;
  auto p = makeProjection(cam, w, h);
  int rays = 0;
  for (int py = 0; py < h; ++py)
    for (int px = 0; px < w; ++px) {
      const double x = std::clamp(px + 0.5, 0.0, w - 1.0);
      const double y = std::clamp(py + 0.5 - 1.0, 0.0, h - 1.0);
      const double u = (x - 0.5) / w, v = 1.0 - (y + 0.5) / h;
      std::optional<Vec3> expected;
      for (const auto& t : d->triangles) {
        const Vec2 &p1 = d->uvs[t[0]], &p2 = d->uvs[t[1]], &p3 = d->uvs[t[2]];
        const double s = (p2.x - p1.x) * (p3.y - p1.y) - (p3.x - p1.x) * (p2.y - p1.y);
        if (s == 0.0) continue;
        const double b1 = ((p2.x - u) * (p3.y - v) - (p3.x - u) * (p2.y - v)) / s;
        const double b2 = ((p3.x - u) * (p1.y - v) - (p1.x - u) * (p3.y - v)) / s;
        const double b3 = ((p1.x - u) * (p2.y - v) - (p2.x - u) * (p1.y - v)) / s;
        if (b1 < 0.0 || b2 < 0.0 || b3 < 0.0) continue;
        expected = b1 * d->positions[t[0]] + b2 * d->positions[t[1]] + b3 * d->positions[t[2]];
        break;
      }
      INFO("pixel " << px << " " << py);
      Ray r;
      const bool got = p->generateRay(Vec2(px + 0.5, py + 0.5), Vec2(0.5), r);
      REQUIRE(got == expected.has_value());
      if (got) {
        ++rays;
        checkVec(r.o, *expected);
      }
    }
  CHECK(rays > w * h / 2);
}
