// The images among the entries of a texture's maps and lists of pigments (POV-Ray's
// image_map as an entry of a pigment_map or of a block pattern's list): each is projected
// from the point its map hands it, and its pixels are loaded with the materials' own.
#pragma once

#include "texture_spec.h"

namespace lucent {

template <class F>
void forEachImageInEntries(const std::vector<TextureMapEntry>& entries, F& f);

// Calls f(const ImageTexture&) for each image inside t's maps and lists, at any depth, in
// order; t itself (a material's own image) is not one of them.
template <class F>
void forEachImageInMaps(const Texture& t, F&& f) {
  if (const auto* p = std::get_if<PatternTexture>(&t)) forEachImageInEntries(p->pigments, f);
  if (const auto* c = std::get_if<CheckerTexture>(&t)) forEachImageInEntries(c->pigments, f);
  if (const auto* h = std::get_if<HexagonTexture>(&t)) forEachImageInEntries(h->pigments, f);
  if (const auto* b = std::get_if<BrickTexture>(&t)) forEachImageInEntries(b->pigments, f);
  if (const auto* a = std::get_if<AverageTexture>(&t)) forEachImageInEntries(a->entries, f);
}

template <class F>
void forEachImageInEntries(const std::vector<TextureMapEntry>& entries, F& f) {
  for (const TextureMapEntry& e : entries) {
    if (const auto* image = std::get_if<ImageTexture>(&e.texture)) f(*image);
    forEachImageInMaps(e.texture, f);
  }
}

}  // namespace lucent
