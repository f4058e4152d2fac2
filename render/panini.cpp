#include "panini.h"

#include "scenegraph/panini_limit.h"

#include <fmt/core.h>

namespace lucent {

namespace {

double angleFromAxis(const Vec3& local) {
  return std::acos(std::clamp(local.z / glm::length(local), -1.0, 1.0));
}

}  // namespace

Vec2 paniniPlane(const Vec3& local, double d) {
  double phi = std::atan2(local.x, local.z);
  double theta = std::atan2(local.y, std::hypot(local.x, local.z));
  double s = (d + 1.0) / (d + std::cos(phi));
  return Vec2(s * std::sin(phi), s * std::tan(theta));
}

bool PaniniProjection::localDirection(double h, double v, Vec3& direction) const {
  // Solve h = (d+1) sin(phi) / (d + cos(phi)) for c = cos(phi): with k = |h| / (d+1),
  // (k^2 + 1) c^2 + 2 k^2 d c + k^2 d^2 - 1 = 0; the larger root is the near branch
  // (the reference code's panini_general_toSphere).
  double k = std::abs(h) / (d_ + 1.0);
  double kk = k * k;
  double discriminant = 1.0 + kk * (1.0 - d_ * d_);
  // For d > 1 it is 0 at the fold h = sqrt((d+1)/(d-1)), where an image framed up to the
  // limit ends; rounding can put that edge a few 1e-16 below 0. Farther out is no direction.
  if (discriminant < 0.0) {
    if (discriminant < -1e-12) return false;
    discriminant = 0.0;
  }
  double c = (-kk * d_ + std::sqrt(discriminant)) / (kk + 1.0);
  double sInverse = (d_ + c) / (d_ + 1.0);   // 1 / S
  double phi = std::atan2(sInverse * h, c);  // sin(phi) = h / S
  double theta = std::atan(v * sInverse);
  if (q_ > 0.0) theta += q_ * (std::atan(v * c) - theta);  // hard squeeze
  double ct = std::cos(theta);
  direction = Vec3(ct * std::sin(phi), std::sin(theta), ct * std::cos(phi));
  return true;
}

PaniniProjection::PaniniProjection(const CameraFrame& frame, const Camera& camera, int width,
                                   int height)
    : Projection(frame, camera, width, height),
      d_(camera.distance),
      q_(camera.verticalCompression) {
  if (!(d_ >= 0.0) || !std::isfinite(d_))
    throw LocatedError(camera.loc, "a panini camera needs distance >= 0");
  if (!(q_ >= 0.0 && q_ <= 1.0))
    throw LocatedError(camera.loc, "a panini camera needs vertical-compression from 0 to 1");
  const double half = 0.5 * radians(camera.fov);
  const double limit = paniniLongitudeLimit(d_);
  const double aspect = static_cast<double>(width) / height;
  // The largest |h| the projection reaches (infinite for d <= 1).
  const double hPeak = d_ > 1.0 ? std::sqrt((d_ + 1.0) / (d_ - 1.0)) : kInf;
  auto hAt = [&](double phi) { return (d_ + 1.0) * std::sin(phi) / (d_ + std::cos(phi)); };
  auto tooWide = [&](const std::string& what) {
    return LocatedError(
        camera.loc, fmt::format("a panini camera with distance {} cannot show {} (fov {} along {})",
                                d_, what, camera.fov,
                                camera.fovAxis == FovAxis::Horizontal ? "horizontal"
                                : camera.fovAxis == FovAxis::Vertical ? "vertical"
                                                                      : "diagonal"));
  };

  switch (camera.fovAxis) {
    case FovAxis::Horizontal:
      if (!(half > 0.0 && paniniHalfFovFits(half, d_)))
        throw tooWide(fmt::format("more than {:.6g} degrees across", 2.0 * limit * 180.0 / kPi));
      halfWidth_ = hAt(half);
      halfHeight_ = halfWidth_ / aspect;
      break;
    case FovAxis::Vertical:
      if (!(half > 0.0 && half < 0.5 * kPi)) throw tooWide("180 degrees or more vertically");
      halfHeight_ = std::tan(half);  // S = 1 on the centre column
      halfWidth_ = halfHeight_ * aspect;
      if (!(halfWidth_ < hPeak)) throw tooWide("an image this wide");
      break;
    case FovAxis::Diagonal: {
      if (!(half > 0.0 && half < kPi)) throw tooWide("180 degrees or more off the axis");
      // The corner (h, h / aspect) must be fov/2 off the axis: bracket by growing h, then
      // bisect (the corner angle grows with h until it passes fov/2).
      auto cornerAngle = [&](double h, bool& ok) {
        Vec3 dir;
        ok = h < hPeak && localDirection(h, h / aspect, dir);
        return ok ? angleFromAxis(dir) : 0.0;
      };
      double lo = 0.0, hi = 1e-3;
      bool ok = true;
      if (std::isfinite(hPeak)) {
        hi = hPeak * (1.0 - 1e-12);  // d > 1: the corner can go no farther than this
        if (cornerAngle(hi, ok) < half) throw tooWide("that much diagonally");
      } else {
        while (cornerAngle(hi, ok) < half) {
          if (!ok || hi > 1e12) throw tooWide("that much diagonally");
          lo = hi;
          hi *= 2.0;
        }
      }
      for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        double mid = 0.5 * (lo + hi);
        (cornerAngle(mid, ok) < half ? lo : hi) = mid;
      }
      halfWidth_ = 0.5 * (lo + hi);
      halfHeight_ = halfWidth_ / aspect;
      break;
    }
  }
  if (q_ > 0.0) {
    Vec3 edge;
    if (!localDirection(halfWidth_, 0.0, edge) || !(edge.z > 0.0))
      throw LocatedError(
          camera.loc,
          "a panini camera with vertical-compression > 0 must stay within 90 degrees "
          "of the view axis horizontally (lower fov or distance)");
  }
}

bool PaniniProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  double sx = 2.0 * film.x / width_ - 1.0;
  double sy = 1.0 - 2.0 * film.y / height_;
  Vec3 local;
  if (!localDirection(sx * halfWidth_, sy * halfHeight_, local)) return false;
  ray = primaryRay(frame_.origin, glm::normalize(frame_.toWorld(local)));
  return true;
}

}  // namespace lucent
