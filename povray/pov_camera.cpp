#include "pov_camera.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace lucent {

PovCameraFrame povCameraFrame(const Camera& camera) {
  const Mat4& m = camera.transform;
  PovCameraFrame f;
  f.location = Vec3(m * Vec4(camera.position, 1.0));
  f.lookAt = Vec3(m * Vec4(camera.lookAt, 1.0));
  f.sky = Mat3(m) * camera.up;
  Vec3 view = f.lookAt - f.location;
  double distance = glm::length(view);
  double side = glm::length(glm::cross(view, f.sky));
  // The renderer's own test (render/camera_frame.cpp): a look-at on the position or an up
  // parallel to the view leaves no frame.
  f.ok = distance > 0.0 && std::isfinite(distance) && side > 1e-9 * glm::length(f.sky) * distance;
  return f;
}

double horizontalFovDegrees(const Camera& camera, int width, int height) {
  if (camera.fovAxis == FovAxis::Horizontal) return camera.fov;  // as written, no round trip
  // Half extents of the image plane at distance 1, as render/pinhole.cpp computes them.
  double half = std::tan(radians(camera.fov) * 0.5);
  double w = width, h = height;
  double halfWidth = half;
  if (camera.fovAxis == FovAxis::Vertical) halfWidth = half * w / h;
  if (camera.fovAxis == FovAxis::Diagonal) halfWidth = half * w / std::hypot(w, h);
  return 2.0 * std::atan(halfWidth) * (180.0 / kPi);
}

namespace {

// "640/480": POV-Ray evaluates the quotient in double, as we would.
std::string ratio(int a, int b) { return fmt::format("{}/{}", a, b); }

void writeFrame(const PovCameraFrame& f, PovWriter& out) {
  out.line("location " + povVector(f.location));
  out.line("sky " + povVector(f.sky));
  out.line("look_at " + povVector(f.lookAt));
}

}  // namespace

void writeCamera(const Camera& camera, const RenderSettings& render, PovWriter& out,
                 PovIssues& issues) {
  const char* type = cameraTypeName(camera.type);
  PovCameraFrame frame = povCameraFrame(camera);
  if (!frame.ok) {
    issues.error(camera.loc,
                 "camera: look-at coincides with the position or up is parallel "
                 "to the view; POV-Ray cannot orient it either");
    return;
  }
  if (camera.near > 0.0 || std::isfinite(camera.far))
    issues.error(camera.loc, fmt::format("camera '{}': near/far clipping has no POV-Ray "
                                         "equivalent (POV-Ray cameras do not clip)",
                                         camera.name.empty() ? type : camera.name));
  const int w = render.width, h = render.height;

  switch (camera.type) {
    case CameraType::Pinhole: {
      if (!(camera.fov > 0.0 && camera.fov < 180.0)) {
        issues.error(camera.loc,
                     fmt::format("pinhole camera: fov {} is outside (0, 180)", camera.fov));
        return;
      }
      out.open("camera");
      out.line("perspective");
      out.line("right -x*" + ratio(w, h));
      out.line("up y");
      out.line("angle " + povNumber(horizontalFovDegrees(camera, w, h)));
      writeFrame(frame, out);
      out.close();
      return;
    }
    case CameraType::Orthographic: {
      // `width` world units across; the height follows the aspect ratio. Both vectors are
      // given so POV-Ray does not rescale them by the look-at distance.
      out.open("camera");
      out.line("orthographic");
      out.line("right -x*" + povNumber(camera.width));
      out.line(fmt::format("up y*{}*{}", povNumber(camera.width), ratio(h, w)));
      writeFrame(frame, out);
      out.close();
      return;
    }
    case CameraType::Fisheye: {
      if (camera.mapping != FisheyeMapping::Equidistant) {
        issues.error(camera.loc,
                     "fisheye camera: mapping 'equisolid' has no POV-Ray "
                     "equivalent (POV-Ray's fisheye is equidistant)");
        return;
      }
      // A diagonal circle reaches the corners: no pixel is outside it.
      if (maxComponent(render.background) > 0.0f && camera.fovAxis != FovAxis::Diagonal)
        issues.warning(camera.loc,
                       "fisheye camera: POV-Ray leaves the pixels outside the "
                       "image circle black; Lucent gives them the background");
      // POV-Ray: u, v in [-1, 1] across the image, scaled by |right| and |up|; the image
      // circle is r = 1 (POV-Ray 3.7's fisheye camera). The renderer's circle spans the image
      // along fov-axis (render/fisheye.h): the width, the height, or the diagonal.
      std::string right, up;
      switch (camera.fovAxis) {
        case FovAxis::Horizontal:
          right = "1";
          up = ratio(h, w);
          break;
        case FovAxis::Vertical:
          right = ratio(w, h);
          up = "1";
          break;
        case FovAxis::Diagonal: {
          double d = std::hypot(static_cast<double>(w), static_cast<double>(h));
          right = povNumber(w / d);
          up = povNumber(h / d);
          break;
        }
      }
      out.open("camera");
      out.line("fisheye");
      out.line("right -x*" + right);
      out.line("up y*" + up);
      out.line("angle " + povNumber(camera.fov));
      writeFrame(frame, out);
      out.close();
      return;
    }
    case CameraType::ThinLens:
    case CameraType::Panini:
    case CameraType::Lenslet:
    case CameraType::Octahedral:
    case CameraType::Cubemap:
    case CameraType::Fibonacci:
      break;
  }
  issues.error(camera.loc, fmt::format("<camera type=\"{}\">: POV-Ray has no equivalent "
                                       "camera (pinhole, orthographic and equidistant fisheye "
                                       "can be exported)",
                                       type));
}

}  // namespace lucent
