// POV-Ray's camera block and its meaning in Lucent (docs/povray-import.md, "Camera").
#pragma once

#include "pov_finish.h"
#include "pov_space.h"

#include "scenegraph/camera.h"
#include "scenegraph/source_loc.h"

#include <optional>
#include <string>
#include <vector>

namespace lucent::sdl {

enum class PovCameraType {
  Perspective,
  Orthographic,
  Fisheye,
  UltraWideAngle,
  Omnimax,
  Panoramic,
  Cylinder,  // cylinder 1 to 4
  Spherical,
  Mesh,  // mesh_camera
};

// What a `camera { ... }` block says, in POV-Ray's space. Each modifier holds the last
// value written; POV-Ray 3.7 applies them in a fixed order whatever the order of writing
// (povCameraVectors). The defaults are POV-Ray's: a scene without a camera gets this one.
struct PovCamera {
  PovCameraType type = PovCameraType::Perspective;
  int cylinderType = 1;
  SourceLoc loc;

  Vec3 location{0.0, 0.0, 0.0};
  Vec3 direction{0.0, 0.0, 1.0};
  // Not derived from the image size: a 4:3 image has pixels 0.25 % wider than tall.
  Vec3 right{1.33, 0.0, 0.0};
  Vec3 up{0.0, 1.0, 0.0};
  Vec3 sky{0.0, 1.0, 0.0};
  std::optional<Vec3> lookAt;
  // `angle`: perspective and orthographic, the full angle across `right`; fisheye, the
  // angle across the image circle (default 90, checked with povray 3.7); spherical, the
  // horizontal angle, with verticalAngle (default: half of it).
  std::optional<double> angle;
  std::optional<double> verticalAngle;
  // Whether `right` and `up` were written (an orthographic camera with neither is sized by
  // its look_at distance).
  bool rightGiven = false;
  bool upGiven = false;
  // translate, rotate, scale, matrix, transform inside the block: applied last.
  PovTransform transform;
  // `normal { }`: bends the primary rays, with its own transforms only (the camera's do not
  // move it); imported by SceneReader::importCameraNormal.
  std::optional<PovNormal> normal;
  SourceLoc normalLoc;
  // Focal blur (aperture, blur_samples [MIN,] MAX, confidence, variance, focal_point, the
  // point in the camera's own space, before its transform): on when the aperture is not 0
  // and blur_samples is given; imported by importFocalBlur.
  struct FocalBlur {
    SourceLoc loc;
    double aperture = 0.0;
    int samples = 0, minSamples = 0;
    double confidence = 0.9, variance = 1.0 / 10000.0;
    std::optional<Vec3> focalPoint;
  };
  FocalBlur blur;
  // mesh_camera { rays distribution [, max_distance] mesh {...}... [smooth] }: the meshes'
  // faces and transforms in Lucent's space; max_distance 0: none.
  struct MeshCamera {
    int raysPerPixel = 1;
    int distribution = 0;
    double maxDistance = 0.0;
    bool smooth = false;
    std::vector<Camera::FaceMesh> meshes;
  };
  MeshCamera mesh;
};

// The camera's vectors once POV-Ray has applied its modifiers, in POV-Ray's space:
// angle sets |direction| from |right| (perspective and orthographic); look_at turns the
// vectors keeping their lengths (and right's handedness); an orthographic camera without
// up and right, or with angle, is scaled by the look_at distance; the transform goes last.
struct PovCameraVectors {
  Vec3 location, direction, right, up;
};
PovCameraVectors povCameraVectors(const PovCamera& camera);

// POV-Ray's primary ray through the centre of pixel (column i, row j from the top) of a
// width x height image, in POV-Ray's space. False where POV-Ray
// traces no ray (outside a fisheye's circle).
bool povPrimaryRay(const PovCamera& camera, const PovCameraVectors& v, int i, int j, int width,
                   int height, Vec3& origin, Vec3& direction);

// The Lucent camera (in Lucent's space) that makes POV-Ray's image at width x height, and
// what of POV-Ray's camera it cannot reproduce (each a sentence for a warning; empty when
// the rays are POV-Ray's). `error` is set instead for a type Lucent has no projection for.
struct CameraImport {
  Camera camera;
  std::vector<std::string> differences;
  std::string error;
};
CameraImport importCamera(const PovCamera& camera, int width, int height);

// POV-Ray's focal blur onto `imported` (importCamera's camera), if it is on: the lens disc
// is half POV-Ray's aperture across; the focus is POV-Ray's focal distance,
// |focal_point − location| or without one |direction|, along the view. What Lucent cannot
// reproduce goes to `differences`.
void importFocalBlur(const PovCamera& camera, Camera& imported,
                     std::vector<std::string>& differences);

}  // namespace lucent::sdl
