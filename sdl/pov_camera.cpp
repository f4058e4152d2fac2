#include "pov_camera.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lucent::sdl {

namespace {

// POV-Ray's own camera angle when none is written (its camera's constructor), which the
// fisheye, ultra_wide_angle and cylinder cameras use without an `angle`.
constexpr double kDefaultAngle = 90.0;

double degreesOf(double radiansValue) { return radiansValue * 180.0 / kPi; }

bool nearlyEqual(double a, double b, double tolerance = 1e-9) {
  return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
}

}  // namespace

PovCameraVectors povCameraVectors(const PovCamera& c) {
  PovCameraVectors v{c.location, c.direction, c.right, c.up};
  const bool framed = c.type == PovCameraType::Perspective || c.type == PovCameraType::Orthographic;
  // angle: |direction| from |right|, so that the angle spans `right`.
  if (c.angle && framed && *c.angle > 0.0 && *c.angle < 180.0)
    v.direction = glm::normalize(v.direction) *
                  (glm::length(v.right) / std::tan(radians(*c.angle) * 0.5) / 2.0);
  // look_at: the vectors turned towards the point, each keeping its length; right keeps
  // the handedness it had with up and direction (a `right -x` camera stays mirrored).
  if (c.lookAt) {
    const double directionLength = glm::length(v.direction), upLength = glm::length(v.up),
                 rightLength = glm::length(v.right);
    const double handedness = glm::dot(glm::cross(v.up, v.direction), v.right);
    const Vec3 d = glm::normalize(*c.lookAt - v.location);
    Vec3 r = glm::cross(c.sky, d);
    // A sky along the view leaves right as it was (POV-Ray's own escape).
    if (std::abs(r.x) < 1e-10 && std::abs(r.y) < 1e-10 && std::abs(r.z) < 1e-10) r = v.right;
    r = glm::normalize(r);
    v.up = glm::cross(d, r) * upLength;
    v.direction = d * directionLength;
    v.right = r * (handedness > 0.0 ? rightLength : -rightLength);
  }
  // An orthographic camera without up and right (or with angle) frames what a perspective
  // one would at the look_at distance (the default look_at <0,0,1> when none is written).
  if (c.type == PovCameraType::Orthographic && ((!c.upGiven && !c.rightGiven) || c.angle)) {
    const double k1 = glm::length(c.lookAt.value_or(Vec3(0.0, 0.0, 1.0)) - v.location);
    const double k2 = glm::length(v.direction);
    if (k1 > 1e-10 && k2 > 1e-10) {
      v.right *= k1 / k2;
      v.up *= k1 / k2;
    }
  }
  v.location = c.transform.point(v.location);
  v.direction = c.transform.vector(v.direction);
  v.right = c.transform.vector(v.right);
  v.up = c.transform.vector(v.up);
  return v;
}

bool povPrimaryRay(const PovCamera& c, const PovCameraVectors& v, int i, int j, int width,
                   int height, Vec3& origin, Vec3& direction) {
  const double x = i + 0.5, y = j + 0.5;
  origin = v.location;
  switch (c.type) {
    case PovCameraType::Perspective: {
      const double x0 = x / width - 0.5, y0 = 0.5 - y / height;
      direction = glm::normalize(v.direction + x0 * v.right + y0 * v.up);
      return true;
    }
    case PovCameraType::Orthographic: {
      const double x0 = x / width - 0.5, y0 = 0.5 - y / height;
      origin = v.location + x0 * v.right + y0 * v.up;
      direction = glm::normalize(v.direction);
      return true;
    }
    case PovCameraType::Fisheye: {
      const double x0 = 2.0 * (x / width - 0.5) * glm::length(v.right);
      const double y0 = 2.0 * (0.5 - y / height) * glm::length(v.up);
      const double rad = std::sqrt(x0 * x0 + y0 * y0);
      if (rad > 1.0) return false;
      const double phi = rad == 0.0 ? 0.0 : std::atan2(y0, x0);
      const double theta = rad * radians(c.angle.value_or(kDefaultAngle)) * 0.5;
      direction = glm::normalize(std::cos(phi) * std::sin(theta) * glm::normalize(v.right) +
                                 std::sin(phi) * std::sin(theta) * glm::normalize(v.up) +
                                 std::cos(theta) * glm::normalize(v.direction));
      return true;
    }
    case PovCameraType::Spherical: {
      const double h = c.angle.value_or(360.0), vAngle = c.verticalAngle.value_or(h * 0.5);
      const double lon = (x / width - 0.5) * radians(h), lat = (0.5 - y / height) * radians(vAngle);
      // The view direction turned about right by -lat, then about up by lon (the
      // right-hand rule of the numbers, as POV-Ray's axis rotation).
      auto turn = [](const Vec3& p, const Vec3& axis, double a) {
        const Vec3 k = glm::normalize(axis);
        return p * std::cos(a) + glm::cross(k, p) * std::sin(a) +
               k * glm::dot(k, p) * (1.0 - std::cos(a));
      };
      direction = glm::normalize(turn(turn(glm::normalize(v.direction), v.right, -lat), v.up, lon));
      return true;
    }
    case PovCameraType::UltraWideAngle: {
      // Unit vectors; |up|/|right| scales the angle down the height.
      const double a = radians(c.angle.value_or(kDefaultAngle));
      const double x0 = (x / width - 0.5) * a;
      const double y0 = (0.5 - y / height) * a * glm::length(v.up) / glm::length(v.right);
      direction = glm::normalize(std::sin(x0) * glm::normalize(v.right) +
                                 std::sin(y0) * glm::normalize(v.up) +
                                 std::cos(x0) * std::cos(y0) * glm::normalize(v.direction));
      return true;
    }
    case PovCameraType::Omnimax: {
      const double aspect = glm::length(v.right) / glm::length(v.up);
      double x0 = 2.0 * x / width - 1.0, y0 = 1.0 - 2.0 * y / height;
      if (aspect > 1.283458) {
        x0 *= aspect / 1.283458;
        y0 = (y0 - 1.0) / 1.283458 + 1.0;
      } else if (aspect > 1.0) {
        y0 = (y0 - 1.0) / aspect + 1.0;
      } else {
        y0 /= aspect;
      }
      const double rad = std::sqrt(x0 * x0 + y0 * y0);
      if (rad > 1.0) return false;
      const double phi = rad == 0.0 ? 0.0 : std::atan2(y0, x0);
      const double theta = 1.411269 * rad - 0.09439 * std::pow(rad, 3) + 0.25674 * std::pow(rad, 5);
      if (std::sin(phi) * std::sin(theta) < std::tan(radians(135.0)) * std::cos(theta))
        return false;
      direction = glm::normalize(std::cos(phi) * std::sin(theta) * glm::normalize(v.right) +
                                 std::sin(phi) * std::sin(theta) * glm::normalize(v.up) +
                                 std::cos(theta) * glm::normalize(v.direction));
      return true;
    }
    case PovCameraType::Panoramic: {
      // The vectors as they are (not normalised).
      const double lon = (1.0 - x / width) * kPi, lat = (0.5 - y / height) * kPi;
      direction = glm::normalize(std::cos(lon) * v.right + std::tan(lat) * v.up +
                                 std::sin(lon) * v.direction);
      return true;
    }
    case PovCameraType::Cylinder: {
      const double a = radians(c.angle.value_or(kDefaultAngle));
      const double x0 = x / width - 0.5, y0 = 0.5 - y / height;
      const Vec3 r = glm::normalize(v.right), u = glm::normalize(v.up),
                 d = glm::normalize(v.direction);
      const double upLength = glm::length(v.up), rightLength = glm::length(v.right);
      switch (c.cylinderType) {
        case 1:
          direction = std::sin(x0 * a) * r + y0 * upLength * u + std::cos(x0 * a) * d;
          break;
        case 2:
          direction = x0 * rightLength * r + std::sin(y0 * a) * u + std::cos(y0 * a) * d;
          break;
        case 3:
          direction = std::sin(x0 * a) * r + std::cos(x0 * a) * d;
          origin += y0 * upLength * u;
          break;
        default:
          direction = std::sin(y0 * a) * u + std::cos(y0 * a) * d;
          origin += x0 * rightLength * r;
          break;
      }
      direction = glm::normalize(direction);
      return true;
    }
    case PovCameraType::Mesh:
      return false;  // its rays come from its faces (render/mesh_camera.h)
  }
  return false;
}

namespace {

const char* povTypeName(PovCameraType t) {
  switch (t) {
    case PovCameraType::Perspective:
      return "perspective";
    case PovCameraType::Orthographic:
      return "orthographic";
    case PovCameraType::Fisheye:
      return "fisheye";
    case PovCameraType::UltraWideAngle:
      return "ultra_wide_angle";
    case PovCameraType::Omnimax:
      return "omnimax";
    case PovCameraType::Panoramic:
      return "panoramic";
    case PovCameraType::Cylinder:
      return "cylinder";
    case PovCameraType::Spherical:
      return "spherical";
    case PovCameraType::Mesh:
      return "mesh_camera";
  }
  return "?";
}

bool perpendicular(const Vec3& d, const Vec3& u, const Vec3& r) {
  return std::abs(glm::dot(d, u)) <= 1e-9 && std::abs(glm::dot(d, r)) <= 1e-9 &&
         std::abs(glm::dot(u, r)) <= 1e-9;
}

// Direction, up and right that are not perpendicular, for the types whose rays are
// direction + x·right + y·up (perspective; orthographic from location + x·right + y·up):
// the camera's image-plane, POV-Ray's right and up in the orthonormal frame Lucent builds
// from the direction and up (right = forward x up), over |direction| for perspective.
void skewedPlane(const PovCameraVectors& v, Camera& camera) {
  const Vec3 d = lucentFromPov(v.direction), u = lucentFromPov(v.up), r = lucentFromPov(v.right);
  const Vec3 forward = glm::normalize(d);
  const Vec3 right = glm::normalize(glm::cross(forward, u));
  const Vec3 up = glm::cross(right, forward);
  const double scale = camera.type == CameraType::Pinhole ? 1.0 / glm::length(d) : 1.0;
  const auto local = [&](const Vec3& w) {
    return scale * Vec3(glm::dot(w, right), glm::dot(w, up), glm::dot(w, forward));
  };
  camera.imagePlane = Camera::ImagePlane{local(r), local(u)};
  // What the plane replaces goes back to its default (a scene written out gives only it).
  const Camera plain;
  camera.mirror = false;  // the sign of right is in the plane's vector
  camera.frameAspect = plain.frameAspect;
  camera.fov = plain.fov;
  camera.fovAxis = plain.fovAxis;
  camera.width = plain.width;
}

// The frame in Lucent's space: position, the unit view direction and up. Lucent builds an
// orthonormal, right-handed frame from them (right = forward x up); what of POV-Ray's
// vectors that cannot hold is said (vectors that are not perpendicular make a skewed
// image, which only `skewable` types reproduce, by skewedPlane).
void placeFrame(const PovCameraVectors& v, Camera& camera, std::vector<std::string>& notes,
                bool skewable = false) {
  const Vec3 location = lucentFromPov(v.location), direction = lucentFromPov(v.direction),
             up = lucentFromPov(v.up), right = lucentFromPov(v.right);
  camera.position = location;
  camera.lookAt = location + glm::normalize(direction);
  camera.up = up;
  const Vec3 d = glm::normalize(direction), u = glm::normalize(up), r = glm::normalize(right);
  if (!perpendicular(d, u, r) && !skewable)
    notes.push_back(
        "the camera's direction, up and right are not perpendicular (POV-Ray: \"Camera vectors "
        "are not perpendicular\"); Lucent's camera frame is orthogonal: the image is skewed "
        "differently");
  // Lucent's frame has right = forward x up; POV-Ray's usual left-handed camera is that
  // frame once z is negated, and a `right -x` camera is its mirror image.
  if (glm::dot(glm::cross(d, u), r) < 0.0) {
    if (camera.type == CameraType::Spherical)
      notes.push_back(
          "the camera's right is on the other side of up and direction than POV-Ray's usual "
          "left-handed frame (a `right -x` camera): Lucent's spherical camera renders "
          "POV-Ray's image upside down");
    else camera.mirror = true;
  }
}

// POV-Ray's image plane is |right| x |up| whatever the image's size: Lucent's frame-aspect
// (pinhole and orthographic), which leaves the pixels square only when it is the image's.
void setFrameAspect(const PovCameraVectors& v, Camera& camera) {
  camera.frameAspect = glm::length(v.right) / glm::length(v.up);
}

// Square pixels, for the fisheye: its image circle spans the image's width, height or
// diagonal in Lucent.
void checkPixels(const PovCameraVectors& v, int width, int height,
                 std::vector<std::string>& notes) {
  const double povAspect = glm::length(v.right) / glm::length(v.up);
  const double imageAspect = static_cast<double>(width) / height;
  if (!nearlyEqual(povAspect, imageAspect, 1e-6))
    notes.push_back(fmt::format(
        "POV-Ray's pixels are not square: |right|/|up| = {:.6g} on a {}x{} image ({:.6g}), "
        "so POV-Ray's image spans {:+.3g} % of the height more than square pixels would; "
        "Lucent's pixels are square (the horizontal field of view is POV-Ray's)",
        povAspect, width, height, imageAspect, 100.0 * (imageAspect / povAspect - 1.0)));
}

}  // namespace

CameraImport importCamera(const PovCamera& pov, int width, int height) {
  CameraImport out;
  Camera& camera = out.camera;
  camera.loc = pov.loc;
  const bool framed =
      pov.type == PovCameraType::Perspective || pov.type == PovCameraType::Orthographic;
  if (framed && pov.angle && *pov.angle >= 180.0) {
    out.error = fmt::format("camera angle {} must be below 180 degrees", *pov.angle);
    return out;
  }
  if (pov.lookAt && !(glm::length(*pov.lookAt - pov.location) > 0.0)) {
    out.error = "the camera's look_at is its location: it looks nowhere";
    return out;
  }
  for (const auto& [vector, name] : {std::pair{pov.direction, "direction"},
                                     std::pair{pov.right, "right"}, std::pair{pov.up, "up"}})
    if (!(glm::length(vector) > 0.0)) {
      out.error = fmt::format("the camera's {} vector has no length", name);
      return out;
    }
  const PovCameraVectors v = povCameraVectors(pov);
  for (const Vec3& w : {v.location, v.direction, v.right, v.up})
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) {
      out.error = "the camera's vectors cannot be worked out (the sky along the view?)";
      return out;
    }
  switch (pov.type) {
    case PovCameraType::Perspective:
      camera.type = CameraType::Pinhole;
      camera.fovAxis = FovAxis::Horizontal;
      camera.fov =
          degreesOf(2.0 * std::atan(0.5 * glm::length(v.right) / glm::length(v.direction)));
      placeFrame(v, camera, out.differences, true);
      setFrameAspect(v, camera);
      if (!perpendicular(glm::normalize(v.direction), glm::normalize(v.up),
                         glm::normalize(v.right)))
        skewedPlane(v, camera);
      return out;
    case PovCameraType::Orthographic:
      camera.type = CameraType::Orthographic;
      camera.width = glm::length(v.right);
      placeFrame(v, camera, out.differences, true);
      setFrameAspect(v, camera);
      if (!perpendicular(glm::normalize(v.direction), glm::normalize(v.up),
                         glm::normalize(v.right)))
        skewedPlane(v, camera);
      return out;
    case PovCameraType::Fisheye: {
      // POV-Ray's image circle has radius width/(2|right|) pixels across and
      // height/(2|up|) up; the angle spans its diameter, equidistantly. Lucent's circle
      // spans the width, the height or the diagonal: the one that is POV-Ray's circle when
      // there is one, else the width with the angle scaled to keep POV-Ray's scale.
      camera.type = CameraType::Fisheye;
      camera.mapping = FisheyeMapping::Equidistant;
      const double angle = pov.angle.value_or(kDefaultAngle);
      const double radius = 0.5 * width / glm::length(v.right);  // pixels
      const double w = width, h = height, diagonal = std::hypot(w, h);
      if (nearlyEqual(radius, 0.5 * h, 1e-6)) {
        camera.fovAxis = FovAxis::Vertical;
        camera.fov = angle * 0.5 * h / radius;
      } else if (nearlyEqual(radius, 0.5 * diagonal, 1e-6)) {
        camera.fovAxis = FovAxis::Diagonal;
        camera.fov = angle * 0.5 * diagonal / radius;
      } else {
        camera.fovAxis = FovAxis::Horizontal;
        camera.fov = angle * 0.5 * w / radius;
        if (!nearlyEqual(radius, 0.5 * w, 1e-6))
          out.differences.push_back(fmt::format(
              "fisheye: POV-Ray's image circle ({:.6g} pixels in radius) is neither the "
              "image's width, height nor diagonal: POV-Ray leaves the pixels outside it black, "
              "Lucent traces them up to the image's width",
              radius));
      }
      if (!(camera.fov <= 360.0)) {
        out.error = fmt::format(
            "fisheye: the image spans {:.6g} degrees across, beyond the 360 Lucent's fisheye "
            "camera can show",
            camera.fov);
        return out;
      }
      placeFrame(v, camera, out.differences);
      checkPixels(v, width, height, out.differences);
      return out;
    }
    case PovCameraType::Spherical:
      camera.type = CameraType::Spherical;
      camera.hAngle = pov.angle.value_or(360.0);
      camera.vAngle = pov.verticalAngle.value_or(camera.hAngle * 0.5);
      placeFrame(v, camera, out.differences);
      return out;
    case PovCameraType::UltraWideAngle: {
      // The angle spans the width; |up|/|right| scales it down the height: Lucent's fov
      // and frame-aspect.
      camera.type = CameraType::UltraWideAngle;
      camera.fovAxis = FovAxis::Horizontal;
      camera.fov = pov.angle.value_or(kDefaultAngle);
      camera.frameAspect = glm::length(v.right) / glm::length(v.up);
      if (!(camera.fov > 0.0 && camera.fov <= 360.0)) {
        out.error = fmt::format(
            "ultra_wide_angle: angle {} is outside Lucent's range (above 0, at most 360)",
            camera.fov);
        return out;
      }
      placeFrame(v, camera, out.differences);
      return out;
    }
    case PovCameraType::Cylinder: {
      camera.type = CameraType::Cylinder;
      camera.cylinderType = pov.cylinderType;
      camera.sweep = pov.angle.value_or(kDefaultAngle);
      const bool alongUp = pov.cylinderType == 1 || pov.cylinderType == 3;
      camera.axisLength = glm::length(alongUp ? v.up : v.right);
      if (!(camera.sweep > 0.0 && camera.sweep <= 360.0)) {
        out.error = fmt::format(
            "cylinder: angle {} is outside Lucent's range (above 0, at most 360)", camera.sweep);
        return out;
      }
      placeFrame(v, camera, out.differences);
      return out;
    }
    case PovCameraType::Panoramic:
      // POV-Ray uses the three vectors at their lengths; only their ratios count.
      camera.type = CameraType::Panoramic;
      camera.rightLength = glm::length(v.right) / glm::length(v.direction);
      camera.upLength = glm::length(v.up) / glm::length(v.direction);
      placeFrame(v, camera, out.differences);
      return out;
    case PovCameraType::Omnimax:
      camera.type = CameraType::Omnimax;
      camera.frameAspect = glm::length(v.right) / glm::length(v.up);
      placeFrame(v, camera, out.differences);
      return out;
    case PovCameraType::Mesh: {
      // The faces give every ray; of the camera's vectors (after its transforms) only the
      // location's z (the offset along each face's normal) and the direction's z (below
      // -EPSILON: the rays reversed) count, as in POV-Ray.
      camera.type = CameraType::Mesh;
      camera.meshes = pov.mesh.meshes;
      camera.raysPerPixel = pov.mesh.raysPerPixel;
      camera.distribution = pov.mesh.distribution;
      camera.smooth = pov.mesh.smooth;
      camera.offset = v.location.z;
      camera.reverse = v.direction.z < -1e-10;
      if (pov.mesh.maxDistance > 0.0) camera.far = pov.mesh.maxDistance;
      return out;
    }
  }
  out.error = fmt::format("'{}' is not supported by Lucent", povTypeName(pov.type));
  return out;
}

void importFocalBlur(const PovCamera& pov, Camera& imported,
                     std::vector<std::string>& differences) {
  const PovCamera::FocalBlur& b = pov.blur;
  if (b.aperture == 0.0 || b.samples <= 0) return;
  Camera::FocalBlur blur;
  blur.loc = b.loc;
  // POV-Ray's lens points lie within aperture/4 of the centre (its grid spans a disc of
  // radius 1/2, scaled by aperture/2); a negative aperture mirrors them.
  blur.aperture = 0.5 * std::abs(b.aperture);
  blur.samples = std::min(b.samples, Camera::kMaxFocalBlurSamples);
  blur.minSamples = std::min(b.minSamples, blur.samples);
  if (b.samples > Camera::kMaxFocalBlurSamples)
    differences.push_back(fmt::format("focal blur: blur_samples {} is above Lucent's {}", b.samples,
                                      Camera::kMaxFocalBlurSamples));
  blur.confidence = b.confidence;
  blur.variance = b.variance;
  // POV-Ray's focal distance, worked out before the camera's transform (checked with
  // povray 3.7: without focal_point it is |direction|).
  PovCamera untransformed = pov;
  untransformed.transform = PovTransform{};
  const Vec3 direction = povCameraVectors(untransformed).direction;
  const double distance =
      b.focalPoint ? glm::length(*b.focalPoint - pov.location) : glm::length(direction);
  // The rays meet at distance × each ray's POV-Ray direction / |direction| (after the
  // transform): a plane (perspective, orthographic) or, where that direction is unit, the
  // sphere of radius distance / |direction| (fisheye, omnimax) or distance (spherical,
  // whose directions are |direction| long).
  double radius = distance;
  const double transformedLength = glm::length(povCameraVectors(pov).direction);
  switch (pov.type) {
    case PovCameraType::Perspective:
    case PovCameraType::Orthographic:
    case PovCameraType::Spherical:
      break;
    case PovCameraType::Fisheye:
    case PovCameraType::Omnimax:
      radius = distance / transformedLength;
      break;
    case PovCameraType::Mesh:
      differences.push_back(
          "focal blur on a mesh camera: left out (Lucent's mesh camera takes no lens)");
      return;
    case PovCameraType::UltraWideAngle:
    case PovCameraType::Cylinder:
    case PovCameraType::Panoramic:
      radius = distance / transformedLength;
      differences.push_back(
          "focal blur on this camera: POV-Ray's rays meet on a surface of its own (its ray "
          "directions are not unit); Lucent focuses on the sphere at POV-Ray's focal distance");
      break;
  }
  // POV-Ray 3.7.0 moves every ray's start to the location plus the lens offset, which
  // undoes the cameras whose rays start elsewhere (fixed in later versions).
  if (pov.type == PovCameraType::Orthographic ||
      (pov.type == PovCameraType::Cylinder && pov.cylinderType >= 3))
    differences.push_back(
        "focal blur on this camera: POV-Ray 3.7.0 starts every ray at the camera's location "
        "(plus the lens offset), so its image is a blur of what the centre sees; Lucent moves "
        "each ray from its own start, as later POV-Ray versions do");
  if (!(radius > 0.0)) {
    differences.push_back("focal blur: the focal point is the camera's location; left out");
    return;
  }
  const Vec3 forward = glm::normalize(imported.lookAt - imported.position);
  blur.focalPoint = imported.position + radius * forward;
  imported.focalBlur = blur;
}

}  // namespace lucent::sdl
