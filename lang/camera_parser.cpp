// <camera> (contract, "<camera>"). Common attributes: name, type (pinhole), position
// (0 0 0), look-at (0 0 -1), up (0 1 0), transform (after position/look-at/up), fov (60),
// fov-axis (horizontal), near (0), far (inf). Each type adds its own attributes; an
// attribute of another type is an error that says which type it belongs to.
#include "element_parsers.h"

#include "scenegraph/panini_limit.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent {

namespace {

const std::vector<std::pair<std::string_view, CameraType>> kCameraTypes{
    {"pinhole", CameraType::Pinhole},
    {"thin-lens", CameraType::ThinLens},
    {"orthographic", CameraType::Orthographic},
    {"fisheye", CameraType::Fisheye},
    {"panini", CameraType::Panini},
    {"lenslet", CameraType::Lenslet},
    {"octahedral", CameraType::Octahedral},
    {"cubemap", CameraType::Cubemap},
    {"fibonacci", CameraType::Fibonacci}};

const std::vector<std::string_view> kCommon{"name",      "type", "position", "look-at", "up",
                                            "transform", "fov",  "fov-axis", "near",    "far"};

const std::vector<std::string_view>& typeAttributes(CameraType t) {
  static const std::vector<std::string_view> none,
      thinLens{"focal-length", "f-stop", "focus-distance"}, ortho{"width"}, fisheye{"mapping"},
      panini{"distance", "vertical-compression"}, lenslet{"lenses", "pitch"}, cubemap{"layout"};
  switch (t) {
    case CameraType::ThinLens:
      return thinLens;
    case CameraType::Orthographic:
      return ortho;
    case CameraType::Fisheye:
      return fisheye;
    case CameraType::Panini:
      return panini;
    case CameraType::Lenslet:
      return lenslet;
    case CameraType::Cubemap:
      return cubemap;
    default:
      return none;
  }
}

// Types whose image is not framed by a field of view.
bool usesFov(CameraType t) {
  return t != CameraType::Orthographic && t != CameraType::Octahedral && t != CameraType::Cubemap &&
         t != CameraType::Fibonacci;
}

double degrees(double radians) { return radians * 180.0 / kPi; }

// The fields of view a panini camera can form whatever the image size: the horizontal fov
// against the fold-back limit of scenegraph/panini_limit.h (the rule render/panini.cpp
// frames the image with), which bounds every fov-axis; a vertical fov below 180; with
// vertical compression, a horizontal fov below 180 (the hard squeeze needs the image within
// 90 degrees of the axis). What depends on the aspect ratio (a vertical fov whose image is
// too wide, a diagonal fov) is refused when the image is framed, at the same file:line:col.
void checkPaniniFov(ElementReader& r, const Camera& cam) {
  const double d = cam.distance, half = 0.5 * radians(cam.fov);
  const double limit = paniniLongitudeLimit(d);
  const std::string dText = fmt::format("{}", d);
  if (!paniniHalfFovFits(half, d)) {
    std::string why = d > 1.0 ? fmt::format(
                                    " (beyond {:.6g} degrees from the axis the "
                                    "projection folds back)",
                                    degrees(limit))
                              : std::string();
    r.attrError("fov", "with distance " + dText + " a panini camera's fov must be below " +
                           fmt::format("{:.6g}", 2.0 * degrees(limit)) + why);
  } else if (cam.fovAxis == FovAxis::Vertical && !(half < 0.5 * kPi)) {
    r.attrError("fov",
                "a panini camera's vertical fov must be below 180 (the latitude at the "
                "top edge stays below 90 degrees)");
  } else if (cam.fovAxis == FovAxis::Horizontal && cam.verticalCompression > 0.0 &&
             !(half < 0.5 * kPi)) {
    r.attrError("fov",
                "with vertical-compression above 0 a panini camera's horizontal fov "
                "must be below 180");
  }
}

}  // namespace

void parseCamera(ElementReader& r) {
  ParseContext& ctx = r.ctx();
  Camera cam;
  cam.loc = r.loc();
  cam.type = r.choice("type", CameraType::Pinhole, kCameraTypes);

  std::vector<std::string_view> allowed = kCommon;
  for (auto a : typeAttributes(cam.type)) allowed.push_back(a);
  r.checkAttributes(allowed, [&](std::string_view attr) -> std::string {
    for (const auto& [name, type] : kCameraTypes)
      for (auto a : typeAttributes(type))
        if (a == attr)
          return "belongs to " + std::string(name) + " cameras; this camera is " +
                 cameraTypeName(cam.type) + " (set type=\"" + std::string(name) + "\")";
    return {};
  });

  if (auto name = r.text("name")) {
    if (!isValidId(*name))
      r.attrError("name",
                  "a camera name must be non-empty and contain no spaces, got '" + *name + "'");
    else if (auto [it, inserted] = ctx.cameraNames.try_emplace(*name, cam.loc); !inserted)
      r.attrError("name",
                  "a camera named '" + *name + "' already exists (at " + it->second.str() + ")");
    else cam.name = *name;
  }
  cam.position = r.vector("position", cam.position);
  cam.lookAt = r.vector("look-at", cam.lookAt);
  cam.up = r.vector("up", cam.up);
  cam.transform = r.transform("transform");

  Vec3 view = cam.lookAt - cam.position;
  if (!(glm::length(view) > 0.0)) {
    r.error("<camera>: 'look-at' must differ from 'position' (the camera would look nowhere)");
  } else if (!(glm::length(glm::cross(view, cam.up)) >
               1e-12 * glm::length(view) * glm::length(cam.up))) {
    r.error(
        "<camera>: 'up' must not be zero or parallel to the viewing direction (look-at - "
        "position)");
  }

  if (usesFov(cam.type)) {
    switch (cam.type) {
      case CameraType::Fisheye:
        cam.fov =
            r.number("fov", cam.fov,
                     NumberRule::between(0.0, 360.0, "an angle above 0 and at most 360", true));
        break;
      case CameraType::Panini:
        cam.fov =
            r.number("fov", cam.fov,
                     NumberRule::between(0.0, 360.0, "an angle between 0 and 360", true, true));
        break;
      default:
        cam.fov =
            r.number("fov", cam.fov,
                     NumberRule::between(0.0, 180.0, "an angle between 0 and 180", true, true));
    }
    cam.fovAxis = r.choice("fov-axis", cam.fovAxis,
                           {{"horizontal", FovAxis::Horizontal},
                            {"vertical", FovAxis::Vertical},
                            {"diagonal", FovAxis::Diagonal}});
  } else {
    for (const char* a : {"fov", "fov-axis"})
      if (r.has(a))
        r.warning(
            std::string("<camera>: '") + a + "' has no effect on cameras of type " +
            cameraTypeName(cam.type) +
            (cam.type == CameraType::Orthographic ? " (their 'width' frames the image)" : ""));
  }

  cam.near = r.number("near", cam.near, NumberRule::nonNegative());
  NumberRule farRule{0.0, kInf, true, false, true, "a positive distance or inf"};
  cam.far = r.number("far", cam.far, farRule);
  if (!(cam.far > cam.near)) r.attrError("far", "'far' must be greater than 'near'");

  switch (cam.type) {
    case CameraType::ThinLens:
      cam.focalLength = r.number("focal-length", cam.focalLength, NumberRule::positive());
      cam.fStop = r.number("f-stop", cam.fStop, NumberRule::positive());
      // 0 (the default) means the distance from position to look-at (camera.h).
      cam.focusDistance = r.number("focus-distance", cam.focusDistance, NumberRule::nonNegative());
      break;
    case CameraType::Orthographic:
      cam.width = r.number("width", cam.width, NumberRule::positive());
      break;
    case CameraType::Fisheye:
      cam.mapping = r.choice(
          "mapping", cam.mapping,
          {{"equidistant", FisheyeMapping::Equidistant}, {"equisolid", FisheyeMapping::Equisolid}});
      break;
    case CameraType::Panini: {
      cam.distance = r.number("distance", cam.distance, NumberRule::nonNegative());
      cam.verticalCompression = r.number("vertical-compression", cam.verticalCompression,
                                         NumberRule::between(0.0, 1.0, "a number from 0 to 1"));
      checkPaniniFov(r, cam);
      break;
    }
    case CameraType::Lenslet: {
      cam.pitch = r.number("pitch", cam.pitch, NumberRule::positive());
      if (auto t = r.text("lenses")) {
        auto list = parseIntegerList(*t);
        if (!list) r.attrError("lenses", list.error);
        else if (list->size() != 2)
          r.attrError("lenses",
                      "expected 2 whole numbers (nx ny), got " + std::to_string(list->size()));
        else if ((*list)[0] < 1 || (*list)[1] < 1 || (*list)[0] > 4096 || (*list)[1] > 4096)
          r.attrError("lenses", "each count must be from 1 to 4096, got '" + *t + "'");
        else {
          cam.lensesX = static_cast<int>((*list)[0]);
          cam.lensesY = static_cast<int>((*list)[1]);
        }
      }
      break;
    }
    case CameraType::Cubemap:
      cam.layout = r.choice("layout", cam.layout,
                            {{"cross", CubemapLayout::Cross}, {"strip", CubemapLayout::Strip}});
      break;
    default:
      break;
  }
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader(ctx, r.file(), n)
        .error("<camera> takes no child elements, got <" + std::string(n.name()) + ">");
  });
  ctx.scene.cameras.push_back(std::move(cam));
}

}  // namespace lucent
