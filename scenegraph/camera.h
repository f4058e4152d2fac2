// Camera descriptions of the contract's <camera>, and the table of camera types and <camera>
// attributes (camera.cpp) that the parser, the schema, `lucent check` and the POV-Ray
// exporter read; render/ turns a Camera into a ray generator (render/projection.h).
#pragma once

#include "attribute_info.h"
#include "pattern.h"
#include "source_loc.h"

#include "primitives/math.h"
#include "primitives/mesh_data.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lucent {

// A new type: its row and attributes in camera.cpp (the rows are an exhaustive switch, so a
// type without its row does not compile) and its projection in render/projection.cpp (an
// exhaustive switch too); docs/architecture.md, "The camera table".
enum class CameraType {
  Pinhole,
  ThinLens,
  Orthographic,
  Fisheye,
  Panini,
  Lenslet,
  Octahedral,
  Cubemap,
  Fibonacci,
  Spherical,
  UltraWideAngle,
  Cylinder,
  Panoramic,
  Omnimax,
  Mesh
};
enum class FovAxis { Horizontal, Vertical, Diagonal };
enum class FisheyeMapping { Equidistant, Equisolid };
enum class CubemapLayout { Cross, Strip };

struct Camera {
  std::string name;
  CameraType type = CameraType::Pinhole;
  SourceLoc loc;

  Vec3 position{0.0};
  Vec3 lookAt{0.0, 0.0, -1.0};
  Vec3 up{0.0, 1.0, 0.0};
  Mat4 transform{1.0};  // applied after position/look-at/up
  double fov = 60.0;    // degrees
  FovAxis fovAxis = FovAxis::Horizontal;
  double near = 0.0;
  double far = kInf;
  // The width / height of what the image shows (pinhole, thin-lens, orthographic); 0: the
  // image's own, square pixels. POV-Ray's |right| / |up|, which keeps its frame when the
  // image size changes.
  double frameAspect = 0.0;
  // The image mirrored left to right (POV-Ray's `right` on the other side: `right -x` in
  // its left-handed space).
  bool mirror = false;
  // Pinhole and orthographic: the image's full width and height as vectors in camera space
  // (x right, y up, z forward at distance 1), for a frame that need not be a rectangle
  // (POV-Ray's right, up and direction when they are not perpendicular). The ray through
  // the image point (s, t), each from -1/2 to 1/2 (left to right, bottom to top), goes along
  // (0, 0, 1) + s·right + t·up (pinhole), or from position + s·right + t·up along forward
  // (orthographic). It replaces fov, fov-axis, frame-aspect and width.
  struct ImagePlane {
    Vec3 right, up;
  };
  std::optional<ImagePlane> imagePlane;

  // thin-lens
  double focalLength = 0.05;  // metres (world units)
  double fStop = 8.0;
  double focusDistance = 0.0;  // 0: the distance from position to look-at
  // orthographic
  double width = 2.0;
  // fisheye
  FisheyeMapping mapping = FisheyeMapping::Equidistant;
  // panini
  double distance = 1.0;
  double verticalCompression = 0.0;
  // lenslet
  int lensesX = 4, lensesY = 4;
  double pitch = 0.1;
  // cubemap
  CubemapLayout layout = CubemapLayout::Cross;
  // spherical: degrees of longitude across the image and of latitude down it (the parser
  // makes vAngle hAngle / 2 unless it is given, as POV-Ray's `angle H` does)
  double hAngle = 360.0;
  double vAngle = 180.0;
  // cylinder: POV-Ray's types 1 to 4 (1, 3: the axis along up; 2, 4: along right; 3, 4:
  // the rays start along the axis instead of at the position), and the image's extent along
  // the axis: at distance 1 from it (1, 2) or in world units (3, 4); 0: square pixels at
  // the image centre.
  int cylinderType = 1;
  double sweep = 90.0;  // degrees about the axis
  double axisLength = 0.0;
  // panoramic: POV-Ray's |right| and |up| over |direction|.
  double rightLength = 1.0;
  double upLength = 1.0;
  // <focal-blur>: POV-Ray's focal blur, for every type but thin-lens (render/focal_blur.h).
  // Each camera sample is the average of up to `samples` rays that start on a lens disc of
  // diameter `aperture` (world units) about the ray's start, in the camera's right-up plane,
  // and meet where the unmoved ray meets the focus surface: the plane through focalPoint
  // parallel to the image (pinhole, orthographic), or the sphere about the ray's start
  // through it (the other types). After minSamples, every 4th ray asks whether the mean is
  // good enough (POV-Ray's confidence test).
  struct FocalBlur {
    SourceLoc loc;
    double aperture = 0.0;
    std::optional<Vec3> focalPoint;  // as position is given (before transform); unset: look-at
    int samples = 37;
    int minSamples = 0;
    double confidence = 0.9;
    double variance = 1.0 / 10000.0;
  };
  std::optional<FocalBlur> focalBlur;
  static constexpr int kMaxFocalBlurSamples = 65536;
  // mesh (POV-Ray's mesh_camera): each ray starts on a face of one of `meshes` and leaves
  // along its normal (render/mesh_camera.h says which face a film point takes).
  struct FaceMesh {
    SourceLoc loc;
    std::shared_ptr<const MeshData> data;  // positions and triangles in order, as written
    Mat4 transform{1.0};                   // before the camera's own
  };
  std::vector<FaceMesh> meshes;
  int raysPerPixel = 1;  // averaged into each sample
  int distribution = 0;  // POV-Ray's distribution type, 0 to 3
  double offset = 0.0;   // the ray's start moved this far along the face's normal
  bool reverse = false;  // the ray leaves against the face's normal
  bool smooth = false;   // distribution 3: the vertex normals interpolated
  static constexpr int kMaxMeshRays = 4096;
  // <normal>: POV-Ray's camera normal. Each primary ray's direction is bent as a surface
  // normal would be, by the pattern at the image point (x0, y0, 0) (render/camera_normal.h).
  std::optional<NormalSpec> normal;
};

// The exporter's side of writing one camera's POV-Ray block (povray/pov_camera.cpp
// implements it): the image the camera frames, POV-Ray's number syntax, and where a row's
// writer puts its lines or says why the camera cannot be written.
class PovCameraOut {
 public:
  virtual ~PovCameraOut() = default;
  virtual int width() const = 0;  // pixels
  virtual int height() const = 0;
  virtual Color background() const = 0;
  virtual std::string number(double v) const = 0;
  // One line of the block, after the type's keyword and before the frame.
  virtual void line(std::string_view text) = 0;
  // What follows the keyword on its line (a cylinder camera's type number).
  virtual void keywordArgument(std::string_view text) = 0;
  // An export error at the camera (then no block is written) or a warning.
  virtual void error(const std::string& message) = 0;
  virtual void warning(const std::string& message) = 0;
};

// How a camera type is written for POV-Ray 3.7. The exporter writes `camera {`, the
// keyword, the writer's lines, the frame (location, sky, look_at after the camera's
// transform) and `}`; a type whose keyword is "" has no POV-Ray twin (an export error).
struct PovCamera {
  std::string_view keyword;  // "perspective"
  std::string_view listed;   // how the export error lists it among those that can be written
  std::function<void(const Camera&, PovCameraOut&)> write;
  // The frame's sky written as -up: for a POV-Ray camera that turns its rays about up
  // whatever the sign of `right`, so that `right -x` alone cannot make it right-handed.
  bool reversedSky;
};

struct CameraTypeInfo {
  CameraType type;
  std::string_view name;  // type="..."
  std::string_view doc;   // one line, for the schema
  // fov's range where a field of view frames the image. Without one, fov and fov-axis have
  // no effect and draw a warning, which ends with noFov (what frames the image) if given.
  std::optional<NumberRule> fov;
  std::string_view noFov;
  // Checks between the type's attributes once every attribute is read (a panini's fov
  // against its distance); may be empty.
  std::function<void(const Camera&, AttributeInput&)> check;
  PovCamera pov;
};
// One row per type, in CameraType's order.
const std::vector<CameraTypeInfo>& cameraTypes();
const CameraTypeInfo& cameraTypeInfo(CameraType type);
const char* cameraTypeName(CameraType type);

// An attribute of <camera>, the types that take it (every type when empty), and how it is
// read into the camera, whose type is already set.
struct CameraAttribute {
  AttributeInfo info;
  std::vector<CameraType> types;
  // Null for the attributes the scene language reads itself: type (first, as it decides
  // the others), name (unique among the scene's cameras) and transform (its syntax).
  std::function<void(Camera&, AttributeInput&)> read;
  bool takenBy(CameraType t) const;
};
// Every attribute <camera> takes, in the schema's order, which is the order they are read.
const std::vector<CameraAttribute>& cameraAttributes();

// The checks between attributes every camera needs (a frame: look-at away from the
// position, up not along the view), then its type's own, once all are read.
void checkCamera(const Camera& camera, AttributeInput& in);

// The frame a camera shows on a width x height image, as a width and a height in
// proportion: frameAspect x 1, or the image's own width x height (kept as integers, so that
// a camera without frame-aspect computes exactly what it always has).
inline void frameProportions(const Camera& camera, int width, int height, double& w, double& h) {
  if (camera.frameAspect > 0.0) {
    w = camera.frameAspect;
    h = 1.0;
  } else {
    w = width;
    h = height;
  }
}

// An ultra-wide-angle camera's angles (degrees) across the width and down the height of a
// width x height image: fov along fov-axis (the diagonal: of the two angles' flat map), in
// proportion to the frame.
void ultraWideAngles(const Camera& camera, int width, int height, double& across, double& down);

// A cylinder camera's extent along its axis on a width x height image: axis-length, or
// where that is 0, the length that makes the pixels square at the image centre.
double cylinderAxisLength(const Camera& camera, int width, int height);

// The full horizontal field of view (degrees) of a pinhole camera on a width x height
// image, whatever its fov-axis (POV-Ray's `angle` spans the `right` vector).
double horizontalFovDegrees(const Camera& camera, int width, int height);

}  // namespace lucent
