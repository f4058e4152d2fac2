// The camera table: one row per CameraType and every attribute of <camera>, with what the
// parser, the schema, `lucent check` and the POV-Ray exporter derive from them
// (docs/architecture.md, "The camera table").
#include "camera.h"

#include "panini_limit.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace lucent {

namespace {

double degrees(double radians) { return radians * 180.0 / kPi; }

// "640/480": POV-Ray evaluates the quotient in double, as we would.
std::string ratio(int a, int b) { return fmt::format("{}/{}", a, b); }

// The fields of view a panini camera can form whatever the image size: the horizontal fov
// against the fold-back limit of panini_limit.h (the rule render/panini.cpp frames the
// image with), which bounds every fov-axis; a vertical fov below 180; with vertical
// compression, a horizontal fov below 180 (the hard squeeze needs the image within 90
// degrees of the axis). What depends on the aspect ratio (a vertical fov whose image is too
// wide, a diagonal fov) is refused when the image is framed, at the same file:line:col.
// POV-Ray's rules for its mesh camera: one ray per pixel for distributions 2 and 3 (their
// rays would all be the same), smooth for distribution 3 only (the others start at the
// face's centroid). The meshes, children of the element, are checked where they are read.
void checkMeshCamera(const Camera& cam, AttributeInput& in) {
  if (cam.distribution >= 2 && cam.raysPerPixel != 1)
    in.attrError("rays-per-pixel", fmt::format("a mesh camera of distribution {} takes one ray "
                                               "per pixel (as POV-Ray: its rays would be the same)",
                                               cam.distribution));
  if (cam.smooth && cam.distribution != 3)
    in.attrError("smooth",
                 "smooth is for a mesh camera of distribution 3 (the others start each ray at "
                 "its face's centroid, along the face's normal), as POV-Ray");
}

void checkPaniniFov(const Camera& cam, AttributeInput& in) {
  const double d = cam.distance, half = 0.5 * radians(cam.fov);
  const double limit = paniniLongitudeLimit(d);
  const std::string dText = fmt::format("{}", d);
  if (!paniniHalfFovFits(half, d)) {
    std::string why = d > 1.0 ? fmt::format(
                                    " (beyond {:.6g} degrees from the axis the "
                                    "projection folds back)",
                                    degrees(limit))
                              : std::string();
    in.attrError("fov", "with distance " + dText + " a panini camera's fov must be below " +
                            fmt::format("{:.6g}", 2.0 * degrees(limit)) + why);
  } else if (cam.fovAxis == FovAxis::Vertical && !(half < 0.5 * kPi)) {
    in.attrError("fov",
                 "a panini camera's vertical fov must be below 180 (the latitude at the "
                 "top edge stays below 90 degrees)");
  } else if (cam.fovAxis == FovAxis::Horizontal && cam.verticalCompression > 0.0 &&
             !(half < 0.5 * kPi)) {
    in.attrError("fov",
                 "with vertical-compression above 0 a panini camera's horizontal fov "
                 "must be below 180");
  }
}

// POV-Ray's writers. POV-Ray is left-handed; our world is right-handed with +y up, so
// `right -x*...` (negative handedness) makes look_at compute right = forward × sky, the
// renderer's frame, with every world coordinate unchanged.

// `right -x` is Lucent's usual frame; a mirrored camera's right is +x.
std::string rightSign(const Camera& camera) { return camera.mirror ? "right " : "right -"; }

// The frame's width / height: the camera's frame-aspect, or the image's.
std::string aspectText(const Camera& camera, const PovCameraOut& out) {
  return camera.frameAspect > 0.0 ? out.number(camera.frameAspect)
                                  : ratio(out.width(), out.height());
}

void writePinhole(const Camera& camera, PovCameraOut& out) {
  if (!(camera.fov > 0.0 && camera.fov < 180.0)) {
    out.error(fmt::format("pinhole camera: fov {} is outside (0, 180)", camera.fov));
    return;
  }
  out.line(rightSign(camera) + "x*" + aspectText(camera, out));
  out.line("up y");
  out.line("angle " + out.number(horizontalFovDegrees(camera, out.width(), out.height())));
}

// `width` world units across; the height follows the aspect ratio. Both vectors are given
// so POV-Ray does not rescale them by the look-at distance.
void writeOrthographic(const Camera& camera, PovCameraOut& out) {
  out.line(rightSign(camera) + "x*" + out.number(camera.width));
  out.line(
      camera.frameAspect > 0.0
          ? fmt::format("up y*{}/{}", out.number(camera.width), out.number(camera.frameAspect))
          : fmt::format("up y*{}*{}", out.number(camera.width), ratio(out.height(), out.width())));
}

void writeFisheye(const Camera& camera, PovCameraOut& out) {
  if (camera.mapping != FisheyeMapping::Equidistant) {
    out.error(
        "fisheye camera: mapping 'equisolid' has no POV-Ray "
        "equivalent (POV-Ray's fisheye is equidistant)");
    return;
  }
  const int w = out.width(), h = out.height();
  // A diagonal circle reaches the corners: no pixel is outside it.
  if (maxComponent(out.background()) > 0.0f && camera.fovAxis != FovAxis::Diagonal)
    out.warning(
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
      right = out.number(w / d);
      up = out.number(h / d);
      break;
    }
  }
  out.line(rightSign(camera) + "x*" + right);
  out.line("up y*" + up);
  out.line("angle " + out.number(camera.fov));
}

// POV-Ray's longitude turns about up whatever the sign of `right`, and its latitude about
// right: with `right -x` alone the image would come out turned by 180 degrees. A reversed
// sky turns POV-Ray's up (and with `right -x`, its right) over, which puts +right at 3/4 of
// the width and up at the top, as the renderer does.
void writeSpherical(const Camera& camera, PovCameraOut& out) {
  if (camera.mirror) {
    out.error("a mirrored spherical camera: POV-Ray's spherical camera cannot be mirrored");
    return;
  }
  out.line("angle " + out.number(camera.hAngle) + ", " + out.number(camera.vAngle));
  out.line("right -x");
  out.line("up y");
}

// POV-Ray's ultra_wide_angle: `angle` spans the width, and |up|/|right| scales it down the
// height (its right, up and direction are normalised, so only that ratio counts).
void writeUltraWideAngle(const Camera& camera, PovCameraOut& out) {
  double across = 0.0, down = 0.0;
  ultraWideAngles(camera, out.width(), out.height(), across, down);
  out.line(rightSign(camera) + "x*" + out.number(across));
  out.line("up y*" + out.number(down));
  out.line("angle " + out.number(across));
}

// POV-Ray's `cylinder N`: `angle` is about the axis; the length of the vector along the
// axis (up for 1 and 3, right for 2 and 4) is the image's extent along it.
void writeCylinder(const Camera& camera, PovCameraOut& out) {
  const std::string length = out.number(cylinderAxisLength(camera, out.width(), out.height()));
  const bool alongUp = camera.cylinderType == 1 || camera.cylinderType == 3;
  out.keywordArgument(std::to_string(camera.cylinderType));
  out.line(rightSign(camera) + "x" + (alongUp ? "" : "*" + length));
  out.line(alongUp ? "up y*" + length : "up y");
  out.line("angle " + out.number(camera.sweep));
}

// POV-Ray's panoramic uses right, up and direction as they are: direction keeps its
// default length 1 through look_at, right and up are written at their lengths.
void writePanoramic(const Camera& camera, PovCameraOut& out) {
  out.line(rightSign(camera) + "x*" + out.number(camera.rightLength));
  out.line("up y*" + out.number(camera.upLength));
}

// POV-Ray's omnimax: |right|/|up| is the frame's aspect ratio.
void writeOmnimax(const Camera& camera, PovCameraOut& out) {
  if (maxComponent(out.background()) > 0.0f)
    out.warning(
        "omnimax camera: POV-Ray leaves the pixels outside the image circle black; Lucent "
        "gives them the background");
  out.line(rightSign(camera) + "x*" + aspectText(camera, out));
  out.line("up y");
}

const NumberRule kFovBelow180 =
    NumberRule::between(0.0, 180.0, "an angle between 0 and 180", true, true);

// The row of each type. The switch has no default, so a CameraType without its row does not
// compile; past the last enumerator it gives nothing, which ends the table (cameraTypes()).
// A row starts with no field of view, no checks and no POV-Ray twin.
const NumberRule kFovTo360 =
    NumberRule::between(0.0, 360.0, "an angle above 0 and at most 360", true);

std::optional<CameraTypeInfo> row(CameraType t) {
  CameraTypeInfo r{t, "", "", std::nullopt, "", nullptr, {"", "", nullptr, false}};
  switch (t) {
    case CameraType::Pinhole:
      r.name = "pinhole";
      r.doc = "Rectilinear perspective (fov, fov-axis).";
      r.fov = kFovBelow180;
      r.pov = {"perspective", "pinhole", writePinhole, false};
      return r;
    case CameraType::ThinLens:
      r.name = "thin-lens";
      r.doc =
          "Gaussian thin-lens depth of field: focal-length, f-stop, focus-distance; aperture "
          "diameter = focal-length / f-stop.";
      r.fov = kFovBelow180;
      return r;
    case CameraType::Orthographic:
      r.name = "orthographic";
      r.doc = "Parallel rays; width = world units across the image (replaces fov).";
      r.noFov = "their 'width' frames the image";
      r.pov = {"orthographic", "orthographic", writeOrthographic, false};
      return r;
    case CameraType::Fisheye:
      r.name = "fisheye";
      r.doc =
          "Fisheye: mapping = equidistant | equisolid; fov may reach 360; outside the image "
          "circle: background.";
      r.fov = NumberRule::between(0.0, 360.0, "an angle above 0 and at most 360", true);
      r.pov = {"fisheye", "equidistant fisheye", writeFisheye, false};
      return r;
    case CameraType::Panini:
      r.name = "panini";
      r.doc = "Generalized Panini projection: distance, vertical-compression.";
      r.fov = NumberRule::between(0.0, 360.0, "an angle between 0 and 360", true, true);
      r.check = checkPaniniFov;
      return r;
    case CameraType::Lenslet:
      r.name = "lenslet";
      r.doc =
          "Light-field camera: lenses = \"nx ny\" pinhole sub-images, pitch = world units "
          "between lens centres.";
      r.fov = kFovBelow180;
      return r;
    case CameraType::Octahedral:
      r.name = "octahedral";
      r.doc = "The full sphere of directions on an octahedral map (square image).";
      return r;
    case CameraType::Cubemap:
      r.name = "cubemap";
      r.doc = "The six 90° faces of a cube; layout = cross (4×3) | strip (6×1).";
      return r;
    case CameraType::Fibonacci:
      r.name = "fibonacci";
      r.doc =
          "Pixel k (row-major) looks along the k-th of width×height Fibonacci-sphere "
          "directions.";
      return r;
    case CameraType::Spherical:
      r.name = "spherical";
      r.doc =
          "Latitude-longitude (equirectangular) image, POV-Ray's spherical camera: h-angle "
          "degrees of longitude across, v-angle of latitude down.";
      r.noFov = "their 'h-angle' and 'v-angle' frame the image";
      r.pov = {"spherical", "spherical", writeSpherical, true};
      return r;
    case CameraType::UltraWideAngle:
      r.name = "ultra-wide-angle";
      r.doc =
          "POV-Ray's ultra_wide_angle: angles grow evenly across the image (fov along fov-axis, "
          "in proportion to frame-aspect), up to 360.";
      r.fov = kFovTo360;
      r.pov = {"ultra_wide_angle", "ultra-wide-angle", writeUltraWideAngle, false};
      return r;
    case CameraType::Cylinder:
      r.name = "cylinder";
      r.doc =
          "POV-Ray's cylinder cameras 1-4 (cylinder-type): sweep degrees about the axis (up or "
          "right), axis-length along it.";
      r.noFov = "their 'sweep' and 'axis-length' frame the image";
      r.pov = {"cylinder", "cylinder", writeCylinder, false};
      return r;
    case CameraType::Panoramic:
      r.name = "panoramic";
      r.doc =
          "POV-Ray's panoramic camera: 180 degrees across, tan(latitude) up (right-length, "
          "up-length).";
      r.noFov = "it shows 180 degrees across; 'right-length' and 'up-length' shape it";
      r.pov = {"panoramic", "panoramic", writePanoramic, false};
      return r;
    case CameraType::Omnimax:
      r.name = "omnimax";
      r.doc =
          "POV-Ray's omnimax camera: a fixed 180-degree dome lens, its circle on frame-aspect; "
          "outside it: background.";
      r.noFov = "its lens is fixed at about 180 degrees across its image circle";
      r.pov = {"omnimax", "omnimax", writeOmnimax, false};
      return r;
    case CameraType::Mesh:
      r.name = "mesh";
      r.doc =
          "POV-Ray's mesh camera: each ray starts on a face of a <mesh> child and leaves along "
          "its normal; distribution picks the face of each film point.";
      r.noFov = "its faces give every ray";
      r.check = checkMeshCamera;
      // Written by povray/pov_mesh_camera.cpp: its block holds meshes, not a frame.
      r.pov = {"mesh_camera", "mesh", nullptr, false};
      return r;
  }
  return std::nullopt;
}

using Read = std::function<void(Camera&, AttributeInput&)>;
using Types = std::vector<CameraType>;

// An attribute's entry. The schema writes the default (default="...") of the attributes
// every camera takes, the Camera's own member value; one that only some types take states
// its default in its documentation, since a schema default would apply to every camera.
CameraAttribute entry(const char* name, AttrType type, std::string defaultText, Types types,
                      Read read, std::string doc) {
  AttributeInfo a;
  a.name = name;
  a.type = type;
  if (types.empty()) a.defaultText = std::move(defaultText);
  a.doc = std::move(doc);
  return {std::move(a), std::move(types), std::move(read)};
}

// The schema's type when the attribute's own type does not give it ("unitInterval").
CameraAttribute schemaType(CameraAttribute a, std::string_view type) {
  a.info.schemaType = type;
  return a;
}

// A number read into m, in the range of rule.
CameraAttribute number(const char* name, double Camera::*m, NumberRule rule, Types types,
                       std::string doc) {
  CameraAttribute a = entry(
      name, AttrType::Number, fmt::format("{}", Camera{}.*m), std::move(types),
      [name, m, rule](Camera& c, AttributeInput& in) { c.*m = in.number(name, c.*m, rule); },
      std::move(doc));
  a.info.rule = rule;
  return a;
}

CameraAttribute vector(const char* name, Vec3 Camera::*m, std::string doc) {
  const Vec3 v = Camera{}.*m;
  return entry(
      name, AttrType::Vector, fmt::format("{} {} {}", v.x, v.y, v.z), {},
      [name, m](Camera& c, AttributeInput& in) { c.*m = in.vector(name, c.*m); }, std::move(doc));
}

// A choice among words in the order of the enumeration E.
template <class E>
Read readChoice(const char* name, E Camera::*m, std::vector<std::string_view> words) {
  return [name, m, words](Camera& c, AttributeInput& in) {
    c.*m = static_cast<E>(in.choice(name, static_cast<size_t>(c.*m), words));
  };
}
template <class E>
CameraAttribute choice(const char* name, E Camera::*m, std::vector<std::string_view> words,
                       std::string_view type, Types types, std::string doc) {
  CameraAttribute a =
      entry(name, AttrType::Choice, std::string(words[static_cast<size_t>(Camera{}.*m)]),
            std::move(types), readChoice(name, m, words), std::move(doc));
  a.info.choices = std::move(words);
  a.info.schemaType = type;
  return a;
}

// What the scene language reads itself (CameraAttribute::read).
CameraAttribute readByLanguage(const char* name, AttrType type, std::string_view schema,
                               std::string defaultText, std::string doc) {
  return schemaType(entry(name, type, std::move(defaultText), {}, nullptr, std::move(doc)), schema);
}

// fov and fov-axis frame the image only where the type gives fov a range; elsewhere they
// have no effect, which is worth a warning (the value is not even read).
void warnNoFov(const Camera& c, const char* attr, AttributeInput& in) {
  if (!in.has(attr)) return;
  const CameraTypeInfo& t = cameraTypeInfo(c.type);
  in.warning(std::string("<camera>: '") + attr + "' has no effect on cameras of type " +
             std::string(t.name) + (t.noFov.empty() ? "" : " (" + std::string(t.noFov) + ")"));
}

void readFov(Camera& c, AttributeInput& in) {
  const CameraTypeInfo& t = cameraTypeInfo(c.type);
  if (t.fov) c.fov = in.number("fov", c.fov, *t.fov);
  else warnNoFov(c, "fov", in);
}

const std::vector<std::string_view> kFovAxes{"horizontal", "vertical", "diagonal"};

void readFovAxis(Camera& c, AttributeInput& in) {
  if (cameraTypeInfo(c.type).fov) readChoice("fov-axis", &Camera::fovAxis, kFovAxes)(c, in);
  else warnNoFov(c, "fov-axis", in);
}

const NumberRule kFarRule{0.0, kInf, true, false, true, "a positive distance or inf"};

// near is read before far (the table's order).
void readFar(Camera& c, AttributeInput& in) {
  c.far = in.number("far", c.far, kFarRule);
  if (!(c.far > c.near)) in.attrError("far", "'far' must be greater than 'near'");
}

void readLenses(Camera& c, AttributeInput& in) {
  auto list = in.integers("lenses");
  if (!list) return;
  if (list->size() != 2)
    in.attrError("lenses", "expected 2 whole numbers (nx ny), got " + std::to_string(list->size()));
  else if ((*list)[0] < 1 || (*list)[1] < 1 || (*list)[0] > 4096 || (*list)[1] > 4096)
    in.attrError("lenses",
                 "each count must be from 1 to 4096, got '" + in.text("lenses").value_or("") + "'");
  else {
    c.lensesX = static_cast<int>((*list)[0]);
    c.lensesY = static_cast<int>((*list)[1]);
  }
}

// Six numbers: the image's right and up vectors in camera space. They replace what frames
// the image otherwise, and must span a plane the view direction crosses.
void readImagePlane(Camera& c, AttributeInput& in) {
  auto list = in.numbers("image-plane");
  if (!list) return;
  if (list->size() != 6) {
    in.attrError("image-plane",
                 "expected 6 numbers (right x y z, up x y z), got " + std::to_string(list->size()));
    return;
  }
  for (const char* other : {"fov", "fov-axis", "frame-aspect", "width"})
    if (in.has(other)) {
      in.attrError("image-plane",
                   std::string("'image-plane' replaces '") + other + "': give one of them");
      return;
    }
  const std::vector<double>& v = *list;
  const Camera::ImagePlane plane{Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])};
  // (right × up)·forward: zero when the vectors are parallel or the plane holds the view.
  const double crossing = glm::cross(plane.right, plane.up).z;
  if (!(std::abs(crossing) > 1e-12 * glm::length(plane.right) * glm::length(plane.up))) {
    in.attrError("image-plane",
                 "right and up must be non-zero, not parallel, and span a plane the view "
                 "direction (0 0 1) crosses");
    return;
  }
  c.imagePlane = plane;
}

std::vector<std::string_view> typeNames() {
  std::vector<std::string_view> names;
  for (const CameraTypeInfo& t : cameraTypes()) names.push_back(t.name);
  return names;
}

}  // namespace

const std::vector<CameraTypeInfo>& cameraTypes() {
  static const std::vector<CameraTypeInfo> table = [] {
    std::vector<CameraTypeInfo> rows;
    // CameraType's enumerators are 0, 1, 2, ...: ask for rows until one is past the last.
    for (int i = 0;; ++i) {
      std::optional<CameraTypeInfo> r = row(static_cast<CameraType>(i));
      if (!r) return rows;
      rows.push_back(std::move(*r));
    }
  }();
  return table;
}

const CameraTypeInfo& cameraTypeInfo(CameraType type) {
  const auto& table = cameraTypes();
  const auto i = static_cast<size_t>(type);
  if (i >= table.size() || table[i].type != type)
    throw std::logic_error("cameraTypes(): the rows are not in CameraType's order");
  return table[i];
}

const char* cameraTypeName(CameraType type) { return cameraTypeInfo(type).name.data(); }

bool CameraAttribute::takenBy(CameraType t) const {
  return types.empty() || std::find(types.begin(), types.end(), t) != types.end();
}

const std::vector<CameraAttribute>& cameraAttributes() {
  using T = CameraType;
  static const std::vector<CameraAttribute> table{
      readByLanguage("name", AttrType::Text, "name", "",
                     "Name used by `lucent render --camera NAME`. Optional."),
      [] {
        CameraAttribute a = readByLanguage("type", AttrType::Choice, "cameraType",
                                           cameraTypeName(Camera{}.type), "");
        a.info.choices = typeNames();
        for (std::string_view name : a.info.choices)
          a.info.doc += (a.info.doc.empty() ? "" : " | ") + std::string(name);
        a.info.doc += ".";
        return a;
      }(),
      vector("position", &Camera::position, "Eye position."),
      vector("look-at", &Camera::lookAt,
             "Point the camera looks at (the default camera looks down -z)."),
      vector("up", &Camera::up,
             "Up direction (need not be perpendicular to the viewing direction, must not be "
             "parallel to it)."),
      readByLanguage("transform", AttrType::Text, "transform", "",
                     "Transform applied to the camera after position/look-at/up. Default: none."),
      // Each type's range (CameraTypeInfo::fov); the schema's is the widest.
      schemaType(entry("fov", AttrType::Number, fmt::format("{}", Camera{}.fov), {}, readFov,
                       "Field of view in degrees along fov-axis. Pinhole and thin-lens: below "
                       "180; fisheye, ultra-wide-angle: up to 360; panini: below 360 and "
                       "limited by distance. Not used by orthographic (width), octahedral, "
                       "cubemap, fibonacci, spherical (h-angle, v-angle), cylinder (sweep, "
                       "axis-length), panoramic, omnimax."),
                 "fieldOfView"),
      [] {
        CameraAttribute a = choice("fov-axis", &Camera::fovAxis, kFovAxes, "fovAxis", {},
                                   "Image axis the fov spans: horizontal | vertical | diagonal.");
        a.read = readFovAxis;  // only where fov frames the image
        return a;
      }(),
      number("near", &Camera::near, NumberRule::nonNegative(), {},
             "tmin of every primary ray (distance along the ray)."),
      [] {
        CameraAttribute a =
            schemaType(entry("far", AttrType::Number, fmt::format("{}", Camera{}.far), {}, readFar,
                             "tmax of every primary ray; must exceed near."),
                       "distanceOrInfinity");
        a.info.rule = kFarRule;
        return a;
      }(),
      number("frame-aspect", &Camera::frameAspect, NumberRule::nonNegative(),
             {T::Pinhole, T::ThinLens, T::Orthographic, T::UltraWideAngle, T::Omnimax},
             "pinhole, thin-lens, orthographic, ultra-wide-angle, omnimax: the width / height "
             "of what the image shows, kept when the image size changes (POV-Ray's |right| / "
             "|up|; pixels are not square when it differs from the image's). Default (or 0): "
             "the image's own."),
      entry(
          "mirror", AttrType::Boolean, "false", {},
          [](Camera& c, AttributeInput& in) { c.mirror = in.boolean("mirror", c.mirror); },
          "true: the image mirrored left to right (POV-Ray's `right` on the other side of up "
          "and direction). Default false."),
      number("focal-length", &Camera::focalLength, NumberRule::positive(), {T::ThinLens},
             "thin-lens: lens focal length in metres (world units); aperture diameter = "
             "focal-length / f-stop. Default 0.05."),
      number("f-stop", &Camera::fStop, NumberRule::positive(), {T::ThinLens},
             "thin-lens: f-number; larger means a smaller aperture and more depth of field. "
             "Default 8."),
      // 0 (the default) means the distance from position to look-at (Camera).
      number("focus-distance", &Camera::focusDistance, NumberRule::nonNegative(), {T::ThinLens},
             "thin-lens: distance of the plane in focus. Default (or 0): the distance from "
             "position to look-at."),
      number("width", &Camera::width, NumberRule::positive(), {T::Orthographic},
             "orthographic: world units across the image (replaces fov). Default 2."),
      choice("mapping", &Camera::mapping, {"equidistant", "equisolid"}, "fisheyeMapping",
             {T::Fisheye}, "fisheye: equidistant (default) | equisolid."),
      number("distance", &Camera::distance, NumberRule::nonNegative(), {T::Panini},
             "panini: the projection's distance parameter d (0 = rectilinear, 1 = cylindrical "
             "stereographic). Default 1."),
      schemaType(number("vertical-compression", &Camera::verticalCompression,
                        NumberRule::between(0.0, 1.0, "a number from 0 to 1"), {T::Panini},
                        "panini: vertical compression in 0..1. Default 0."),
                 "unitInterval"),
      entry("image-plane", AttrType::NumberList, "", {T::Pinhole, T::Orthographic}, readImagePlane,
            "pinhole, orthographic: \"rx ry rz ux uy uz\", the image's full width (right) and "
            "height (up) as camera-space vectors (x right, y up, z forward): the ray through "
            "image point (s, t), each -1/2 to 1/2, goes along (0 0 1) + s*right + t*up "
            "(orthographic: from position + s*right + t*up along the view). A frame that need "
            "not be a rectangle (POV-Ray's right, up and direction when not perpendicular); "
            "replaces fov, fov-axis, frame-aspect and width."),
      schemaType(entry("lenses", AttrType::IntegerList, "", {T::Lenslet}, readLenses,
                       "lenslet: \"nx ny\", the grid of lenslets (one pinhole sub-image each), "
                       "each 1 to 4096. Default 4 4."),
                 "integerPair"),
      number("pitch", &Camera::pitch, NumberRule::positive(), {T::Lenslet},
             "lenslet: world units between lens centres. Default 0.1."),
      choice("layout", &Camera::layout, {"cross", "strip"}, "cubemapLayout", {T::Cubemap},
             "cubemap: cross (4×3, default) | strip (6×1)."),
      schemaType(number("h-angle", &Camera::hAngle,
                        NumberRule::between(0.0, 360.0, "an angle above 0 and at most 360", true),
                        {T::Spherical},
                        "spherical: degrees of longitude across the image, centred on the view "
                        "direction: the left edge at -h-angle/2, the right edge at +h-angle/2, "
                        "right at +90; above 0, at most 360. Default 360."),
                 "fieldOfView"),
      // After h-angle, whose half is its default.
      [] {
        const NumberRule rule =
            NumberRule::between(0.0, 180.0, "an angle above 0 and at most 180", true);
        CameraAttribute a = number("v-angle", &Camera::vAngle, rule, {T::Spherical},
                                   "spherical: degrees of latitude down the image, centred on "
                                   "the view direction: the top edge at +v-angle/2 (towards up), "
                                   "the bottom edge at -v-angle/2; above 0, at most 180. "
                                   "Default: half of h-angle (180).");
        a.read = [rule](Camera& c, AttributeInput& in) {
          // The camera's own value is the default handed to the input, as every reader of
          // the table does, so that the scene writer reads it back (lang/attribute_probe.h).
          c.vAngle = in.has("v-angle") ? in.number("v-angle", c.vAngle, rule) : 0.5 * c.hAngle;
        };
        return a;
      }(),
      schemaType(
          entry(
              "cylinder-type", AttrType::Number, "", {T::Cylinder},
              [](Camera& c, AttributeInput& in) {
                c.cylinderType =
                    static_cast<int>(in.integer("cylinder-type", c.cylinderType, 1, 4));
              },
              "cylinder: POV-Ray's cylinder camera type. 1: the axis along up through the "
              "position, sweep across the width; 2: the axis along right, sweep down the height; "
              "3 and 4: as 1 and 2, with each ray starting on the axis level with its pixel "
              "(parallel along the axis). Default 1."),
          "cylinderCameraType"),
      schemaType(number("sweep", &Camera::sweep, kFovTo360, {T::Cylinder},
                        "cylinder: degrees about the axis across the image: across the width "
                        "for cylinder-type 1 and 3, down the height for 2 and 4; above 0, at "
                        "most 360. Default 90 (POV-Ray's)."),
                 "fieldOfView"),
      number("axis-length", &Camera::axisLength, NumberRule::nonNegative(), {T::Cylinder},
             "cylinder: the image's extent along the axis, at distance 1 from it (types 1 "
             "and 2) or in world units (3 and 4); POV-Ray's |up| (1, 3) or |right| (2, 4). "
             "Default (or 0): square pixels at the image centre."),
      number("right-length", &Camera::rightLength, NumberRule::positive(), {T::Panoramic},
             "panoramic: POV-Ray's |right| / |direction|: the ray at longitude lon (180 at "
             "the left edge, 0 at the right) and latitude lat goes along cos(lon) "
             "right-length right + tan(lat) up-length up + sin(lon) forward. Default 1."),
      number("up-length", &Camera::upLength, NumberRule::positive(), {T::Panoramic},
             "panoramic: POV-Ray's |up| / |direction| (see right-length). Default 1."),
      schemaType(entry(
                     "rays-per-pixel", AttrType::Number, "", {T::Mesh},
                     [](Camera& c, AttributeInput& in) {
                       c.raysPerPixel = static_cast<int>(
                           in.integer("rays-per-pixel", c.raysPerPixel, 1, Camera::kMaxMeshRays));
                     },
                     "mesh: rays averaged into each camera sample, 1 to 4096 (distribution 0: "
                     "ray r from mesh r, at most the number of meshes; 2 and 3: 1). Default 1."),
                 "imageSize"),
      schemaType(entry(
                     "distribution", AttrType::Number, "", {T::Mesh},
                     [](Camera& c, AttributeInput& in) {
                       c.distribution =
                           static_cast<int>(in.integer("distribution", c.distribution, 0, 3));
                     },
                     "mesh: which face a film point takes (POV-Ray's distribution type). 0: face "
                     "row * width + column of mesh r for ray r; 1: the same index over the "
                     "meshes' faces in turn; 2: the meshes side by side across the image; 3: "
                     "the face whose uvs hold the film point's (u, v), of the first mesh. "
                     "Default 0."),
                 "meshCameraDistribution"),
      number("offset", &Camera::offset, NumberRule::any(), {T::Mesh},
             "mesh: the ray's start moved this far along the face's normal (POV-Ray's "
             "location z). Default 0."),
      entry(
          "reverse", AttrType::Boolean, "", {T::Mesh},
          [](Camera& c, AttributeInput& in) { c.reverse = in.boolean("reverse", c.reverse); },
          "mesh: true: the rays leave against the faces' normals (POV-Ray's direction z below "
          "0). Default false."),
      entry(
          "smooth", AttrType::Boolean, "", {T::Mesh},
          [](Camera& c, AttributeInput& in) { c.smooth = in.boolean("smooth", c.smooth); },
          "mesh, distribution 3: true: the ray leaves along the mesh's vertex normals "
          "interpolated at its start (POV-Ray's smooth). Default false."),
  };
  return table;
}

void checkCamera(const Camera& cam, AttributeInput& in) {
  const Vec3 view = cam.lookAt - cam.position;
  if (!(glm::length(view) > 0.0)) {
    in.error("<camera>: 'look-at' must differ from 'position' (the camera would look nowhere)");
  } else if (!(glm::length(glm::cross(view, cam.up)) >
               1e-12 * glm::length(view) * glm::length(cam.up))) {
    in.error(
        "<camera>: 'up' must not be zero or parallel to the viewing direction (look-at - "
        "position)");
  }
  if (const auto& check = cameraTypeInfo(cam.type).check) check(cam, in);
}

void ultraWideAngles(const Camera& camera, int width, int height, double& across, double& down) {
  double w = 0.0, h = 0.0;
  frameProportions(camera, width, height, w, h);
  // The angles make a flat map, w x h in proportion; fov spans its width, height or
  // diagonal.
  switch (camera.fovAxis) {
    case FovAxis::Horizontal:
      across = camera.fov;
      down = camera.fov * h / w;
      break;
    case FovAxis::Vertical:
      down = camera.fov;
      across = camera.fov * w / h;
      break;
    case FovAxis::Diagonal:
      across = camera.fov * w / std::hypot(w, h);
      down = camera.fov * h / std::hypot(w, h);
      break;
  }
}

double cylinderAxisLength(const Camera& camera, int width, int height) {
  if (camera.axisLength > 0.0) return camera.axisLength;
  // The angle per pixel about the axis times the pixels along it (at distance 1).
  const double angle = radians(camera.sweep);
  const bool alongUp = camera.cylinderType == 1 || camera.cylinderType == 3;
  return alongUp ? angle * height / width : angle * width / height;
}

double horizontalFovDegrees(const Camera& camera, int width, int height) {
  if (camera.fovAxis == FovAxis::Horizontal) return camera.fov;  // as written, no round trip
  // Half extents of the image plane at distance 1, as render/pinhole.cpp computes them.
  double half = std::tan(radians(camera.fov) * 0.5);
  double w = 0.0, h = 0.0;
  frameProportions(camera, width, height, w, h);
  double halfWidth = half;
  if (camera.fovAxis == FovAxis::Vertical) halfWidth = half * w / h;
  if (camera.fovAxis == FovAxis::Diagonal) halfWidth = half * w / std::hypot(w, h);
  return 2.0 * std::atan(halfWidth) * (180.0 / kPi);
}

}  // namespace lucent
