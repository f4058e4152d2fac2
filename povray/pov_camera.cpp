#include "pov_camera.h"

#include "pov_mesh_camera.h"
#include "pov_patterns.h"

#include <fmt/core.h>

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

namespace {

// A row's writer's view of the export: its lines are kept until it has finished, so that
// a camera it refuses writes nothing.
class CameraLines final : public PovCameraOut {
 public:
  CameraLines(const Camera& camera, const RenderSettings& render, PovIssues& issues)
      : camera_(camera), render_(render), issues_(issues) {}

  int width() const override { return render_.width; }
  int height() const override { return render_.height; }
  Color background() const override { return render_.background; }
  std::string number(double v) const override { return povNumber(v); }
  void line(std::string_view text) override { lines_.emplace_back(text); }
  void keywordArgument(std::string_view text) override { argument_ = text; }
  void error(const std::string& message) override {
    issues_.error(camera_.loc, message);
    failed_ = true;
  }
  void warning(const std::string& message) override { issues_.warning(camera_.loc, message); }

  bool failed() const { return failed_; }
  const std::vector<std::string>& lines() const { return lines_; }
  const std::string& argument() const { return argument_; }

 private:
  const Camera& camera_;
  const RenderSettings& render_;
  PovIssues& issues_;
  std::vector<std::string> lines_;
  std::string argument_;
  bool failed_ = false;
};

// "pinhole, orthographic and equidistant fisheye": the types POV-Ray can take.
std::string exportableTypes() {
  std::vector<std::string_view> names;
  for (const CameraTypeInfo& t : cameraTypes())
    if (!t.pov.keyword.empty()) names.push_back(t.pov.listed);
  std::string list;
  for (size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : (i + 1 == names.size() ? " and " : ", ")) + std::string(names[i]);
  return list;
}

// POV-Ray's focal blur: aperture twice the lens disc's diameter (POV-Ray's lens points lie
// within a quarter of its aperture from the centre), the focus given as a point on the view
// axis at POV-Ray's focal distance, |focal_point − location|, along `direction`. `normal`
// is the image plane's (forward when it is a rectangle).
void writeFocalBlur(const Camera& camera, const PovCameraFrame& frame, const Vec3& forward,
                    const Vec3& normal, PovWriter& out, PovIssues& issues) {
  const Camera::FocalBlur& blur = *camera.focalBlur;
  const Vec3 focal = Vec3(camera.transform * Vec4(blur.focalPoint.value_or(camera.lookAt), 1.0));
  const Vec3 toFocal = focal - frame.location;
  double distance = glm::length(toFocal);
  if (camera.type == CameraType::Pinhole || camera.type == CameraType::Orthographic)
    distance = glm::dot(toFocal, normal) / glm::dot(forward, normal);
  else if (camera.type == CameraType::Panoramic || camera.type == CameraType::UltraWideAngle ||
           camera.type == CameraType::Cylinder)
    issues.warning(blur.loc,
                   fmt::format("focal blur on a {} camera: POV-Ray focuses its rays on another "
                               "surface than Lucent's sphere (its ray directions are not unit)",
                               cameraTypeName(camera.type)));
  if (camera.type == CameraType::Orthographic ||
      (camera.type == CameraType::Cylinder && camera.cylinderType >= 3))
    issues.warning(blur.loc,
                   fmt::format("focal blur on a {} camera: POV-Ray 3.7.0 starts every ray at the "
                               "location (plus the lens offset), so its image is a blur of what "
                               "the centre sees",
                               cameraTypeName(camera.type)));
  if (!(distance > 0.0)) {
    issues.error(blur.loc, "focal blur: the focal point is not in front of the camera");
    return;
  }
  out.line("aperture " + povNumber(2.0 * blur.aperture));
  out.line("blur_samples " + (blur.minSamples > 0 ? std::to_string(blur.minSamples) + ", " : "") +
           std::to_string(blur.samples));
  out.line("confidence " + povNumber(blur.confidence));
  out.line("variance " + povNumber(blur.variance));
  out.line("focal_point " + povVector(frame.location + distance * forward));
}

// A camera whose image-plane is not a rectangle: POV-Ray's direction, right and up as
// world vectors, without look_at (which would make them perpendicular). POV-Ray's rays,
// direction + x·right + y·up (orthographic: from location + x·right + y·up), are the
// renderer's: its frame is forward, right = forward × sky (mirrored if asked), up =
// right × forward.
void writeImagePlane(const Camera& camera, const PovCameraFrame& frame, PovWriter& out,
                     PovIssues& issues) {
  const Vec3 forward = glm::normalize(frame.lookAt - frame.location);
  Vec3 right = glm::normalize(glm::cross(forward, frame.sky));
  const Vec3 up = glm::cross(right, forward);
  if (camera.mirror) right = -right;
  const auto world = [&](const Vec3& v) { return v.x * right + v.y * up + v.z * forward; };
  out.open("camera");
  out.line(cameraTypeInfo(camera.type).pov.keyword);
  out.line("location " + povVector(frame.location));
  out.line("direction " + povVector(forward));
  out.line("right " + povVector(world(camera.imagePlane->right)));
  out.line("up " + povVector(world(camera.imagePlane->up)));
  if (camera.focalBlur)
    writeFocalBlur(camera, frame, forward,
                   glm::cross(world(camera.imagePlane->right), world(camera.imagePlane->up)), out,
                   issues);
  if (camera.normal) writeNormal(*camera.normal, out);
  out.close();
}

}  // namespace

void writeCamera(const Camera& camera, const RenderSettings& render, PovWriter& out,
                 PovIssues& issues) {
  const CameraTypeInfo& type = cameraTypeInfo(camera.type);
  if (camera.type == CameraType::Mesh) {
    writeMeshCamera(camera, out, issues);
    return;
  }
  PovCameraFrame frame = povCameraFrame(camera);
  if (!frame.ok) {
    issues.error(camera.loc,
                 "camera: look-at coincides with the position or up is parallel "
                 "to the view; POV-Ray cannot orient it either");
    return;
  }
  if (camera.near > 0.0 || std::isfinite(camera.far))
    issues.error(camera.loc,
                 fmt::format("camera '{}': near/far clipping has no POV-Ray "
                             "equivalent (POV-Ray cameras do not clip)",
                             camera.name.empty() ? type.name : std::string_view(camera.name)));
  if (type.pov.keyword.empty()) {
    issues.error(camera.loc, fmt::format("<camera type=\"{}\">: POV-Ray has no equivalent "
                                         "camera ({} can be exported)",
                                         type.name, exportableTypes()));
    return;
  }
  if (camera.imagePlane) {
    writeImagePlane(camera, frame, out, issues);
    return;
  }
  CameraLines lines(camera, render, issues);
  type.pov.write(camera, lines);
  if (lines.failed()) return;
  out.open("camera");
  out.line(std::string(type.pov.keyword) +
           (lines.argument().empty() ? "" : " " + lines.argument()));
  for (const std::string& l : lines.lines()) out.line(l);
  out.line("location " + povVector(frame.location));
  out.line("sky " + povVector(type.pov.reversedSky ? -frame.sky : frame.sky));
  out.line("look_at " + povVector(frame.lookAt));
  if (camera.focalBlur) {
    const Vec3 forward = glm::normalize(frame.lookAt - frame.location);
    writeFocalBlur(camera, frame, forward, forward, out, issues);
  }
  // Lucent's coordinates are written unchanged and POV-Ray's image point is Lucent's, so the
  // normal bends the same rays the same way.
  if (camera.normal) writeNormal(*camera.normal, out);
  out.close();
}

}  // namespace lucent
