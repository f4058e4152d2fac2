// How many arrangements POV-Ray 3.7's pavement pattern has for each number of sides and of
// tiles (its parser's limits), for the parsers that check `pattern N`.
#pragma once

namespace lucent {

// The arrangements of tiles of `tiles` cells with `sides` sides: 0 where POV-Ray has none
// (sides other than 3, 4 and 6, tiles outside 1..6, or 6 tiles of hexagons).
constexpr int pavementArrangements(int sides, int tiles) {
  constexpr int kTriangles[] = {1, 1, 1, 3, 4, 12};
  constexpr int kSquares[] = {1, 1, 2, 5, 12, 35};
  constexpr int kHexagons[] = {1, 1, 3, 7, 22, 0};
  if (tiles < 1 || tiles > 6) return 0;
  if (sides == 3) return kTriangles[tiles - 1];
  if (sides == 4) return kSquares[tiles - 1];
  if (sides == 6) return kHexagons[tiles - 1];
  return 0;
}

}  // namespace lucent
