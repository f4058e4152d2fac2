// Camera descriptions of the contract's <camera>; render/ turns them into ray generators.
#pragma once

#include "source_loc.h"

#include "primitives/math.h"

#include <string>

namespace lucent {

enum class CameraType {
  Pinhole,
  ThinLens,
  Orthographic,
  Fisheye,
  Panini,
  Lenslet,
  Octahedral,
  Cubemap,
  Fibonacci
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
};

const char* cameraTypeName(CameraType t);

}  // namespace lucent
