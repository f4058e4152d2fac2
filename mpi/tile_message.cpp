#include "tile_message.h"

#include "messages.h"

#include <stdexcept>

namespace lucent::mpi {

std::vector<char> pack(const TileOrder& o) {
  Writer w;
  w.put<int32_t>(o.frame);
  w.put<uint64_t>(o.index);
  for (int v : {o.rect.x0, o.rect.y0, o.rect.x1, o.rect.y1}) w.put<int32_t>(v);
  return std::move(w.bytes);
}

TileOrder unpackOrder(const std::vector<char>& bytes) {
  Reader r(bytes);
  TileOrder o;
  o.frame = r.get<int32_t>();
  o.index = r.get<uint64_t>();
  o.rect.x0 = r.get<int32_t>();
  o.rect.y0 = r.get<int32_t>();
  o.rect.x1 = r.get<int32_t>();
  o.rect.y1 = r.get<int32_t>();
  return o;
}

std::vector<char> pack(const TileResult& t) {
  Writer w;
  const RenderResult& r = t.result;
  w.put<int32_t>(t.frame);
  w.put<uint64_t>(t.index);
  w.put<double>(r.seconds);
  w.put<uint8_t>(r.cancelled ? 1 : 0);
  const RayStats& s = r.stats;
  for (uint64_t v : {s.primary, s.shadow, s.reflected, s.refracted, s.queries, s.shadowCacheHits})
    w.put<uint64_t>(v);
  for (size_t k = 0; k < kTestSlots; ++k) w.put<uint64_t>(s.tests[k]);
  w.put<int32_t>(r.image.width);
  w.put<int32_t>(r.image.height);
  w.putBytes(r.image.pixels.data(), r.image.pixels.size() * sizeof(Color));
  return std::move(w.bytes);
}

TileResult unpackResult(const std::vector<char>& bytes) {
  Reader r(bytes);
  TileResult t;
  RenderResult& out = t.result;
  t.frame = r.get<int32_t>();
  t.index = r.get<uint64_t>();
  out.seconds = r.get<double>();
  out.cancelled = r.get<uint8_t>() != 0;
  RayStats& s = out.stats;
  for (uint64_t* v :
       {&s.primary, &s.shadow, &s.reflected, &s.refracted, &s.queries, &s.shadowCacheHits})
    *v = r.get<uint64_t>();
  for (size_t k = 0; k < kTestSlots; ++k) s.tests[k] = r.get<uint64_t>();
  const int width = r.get<int32_t>(), height = r.get<int32_t>();
  const std::string pixels = r.getString();
  if (width < 0 || height < 0 || pixels.size() != size_t(width) * size_t(height) * sizeof(Color))
    throw std::runtime_error("a tile's pixels from another rank are not its size");
  out.image = Image(width, height);
  std::memcpy(out.image.pixels.data(), pixels.data(), pixels.size());
  return t;
}

}  // namespace lucent::mpi
