// The scene reader: POV-Ray's scene items (objects, textures, the camera, lights, settings)
// read from the language core's token stream into the pov_* structs, and mapped with them
// onto a Lucent scene (docs/povray-import.md, "The scene reader").
//
// An object is read into a PovObject (its shape already in Lucent's space, its transforms
// and texture still POV-Ray's) so that `#declare`d objects can be modified by
// `object { X ... }` as POV-Ray modifies them; it becomes scene-graph nodes when placed in
// the scene. The read_*.cpp files hold the blocks, each named after what it reads.
#pragma once

#include "item_reader.h"
#include "open_operands.h"
#include "options.h"
#include "pov_camera.h"
#include "pov_finish.h"
#include "pov_light.h"
#include "pov_settings.h"
#include "pov_space.h"
#include "read_support.h"
#include "shared_values.h"
#include "token_stream.h"

#include "lang/diagnostics.h"
#include "scenegraph/material_sharing.h"
#include "scenegraph/object_pattern.h"
#include "scenegraph/pigment_function.h"
#include "scenegraph/scene.h"

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace lucent::sdl {

struct MeshBuild;  // read_shapes.cpp

struct PovTextureMapEntry;

// A texture of one layer: its pigment, normal and finish; or a map of textures.
struct PovTexture {
  PovPigment pigment;
  std::optional<PovNormal> normal;
  PovFinish finish;
  // The declared texture (or material) it is, as written and unchanged: `texture { T }`;
  // empty once anything changes it. The objects that share it share one named material.
  std::string name;
  // Which declaration of that name (a scene may declare T again, in a loop): the number
  // of the #declare that made it, counted from 1.
  uint64_t declaration = 0;
  // Moved (transformed, or mapped at (u, v)) since it was declared: its patterns no longer
  // lie as the declaration's (an unpatterned texture keeps its name regardless).
  bool moved = false;
  // A layered texture (`texture { A } texture { B }`): this is the top layer, the one a
  // later pigment, normal or finish changes, as in POV-Ray; `below` holds the layers under
  // it, bottom first.
  std::vector<PovTexture> below;
  // A pattern of textures (`texture { gradient y texture_map { [0 A] [1 B] } }`, `checker
  // texture { A } texture { B }`): the pattern with its transforms, and the entries, whose
  // own transforms lead from the map's pattern space (POV-Ray evaluates an entry at the
  // map's point). The pigment, normal and finish are then unused.
  PovPigment mapPattern;
  std::vector<PovTextureMapEntry> mapEntries;

  bool mapped() const { return !mapEntries.empty(); }
  // Some pigment or normal of it (a layer's, a map's, an entry's) is read at the shape's (u, v).
  bool uvMapped() const {
    if ((pigment.uv && pigment.patterned()) || mapPattern.uv || (normal && normal->uv)) return true;
    for (const PovTexture& layer : below)
      if (layer.uvMapped()) return true;
    for (const auto& e : mapEntries)
      if (entryUvMapped(e)) return true;
    return false;
  }
  static bool entryUvMapped(const PovTextureMapEntry& e);
  bool patterned() const {
    if (mapped()) return true;
    if (pigment.patterned() || normal.has_value()) return true;
    for (const PovTexture& layer : below)
      if (layer.patterned()) return true;
    return false;
  }
  // `texture { ... translate ... }`: moves what the texture holds, every layer of it.
  void transform(const PovTransform& m) {
    if (!m.isIdentity()) moved = true;
    pigment.transform = pigment.transform.then(m);
    if (normal) normal->transform = normal->transform.then(m);
    for (PovTexture& layer : below) layer.transform(m);
    // A map's entries follow its pattern's space.
    mapPattern.transform = mapPattern.transform.then(m);
  }
};

struct PovTextureMapEntry {
  double at = 0.0;
  PovTexture texture;
};
inline bool PovTexture::entryUvMapped(const PovTextureMapEntry& e) { return e.texture.uvMapped(); }

// `texture { under } texture { top }`: the layers of top (itself perhaps layered) over
// those of under.
inline PovTexture layered(PovTexture under, PovTexture top) {
  std::vector<PovTexture> below = std::move(under.below);
  under.below.clear();
  below.push_back(std::move(under));
  for (PovTexture& layer : top.below) below.push_back(std::move(layer));
  top.below = std::move(below);
  top.name.clear();  // no longer a declared texture as it is
  return top;
}

// One object as POV-Ray holds it: a shape, a CSG operation of others, or a light source.
struct PovObject {
  std::string keyword;  // "sphere", "union", "light_source"...
  SourceLoc loc;
  NodeKind kind = NodeKind::Shape;
  SharedOptional<ShapeSpec> shape;  // in Lucent's space (z negated)
  // A mesh's or mesh2's triangles as read, in order, before Lucent's repairs (in Lucent's
  // space): the faces a mesh camera takes.
  std::shared_ptr<const MeshData> faces;
  SharedOptional<PovLight> light;                // kind == Light
  SharedValue<std::vector<PovObject>> children;  // shared by copies until one changes
  PovTransform transform;                        // the object's transforms, in POV-Ray's space
  // Its texture, whose transforms lead from pattern space to this object's own space
  // (before `transform`): a texture written among the transforms is carried back by the
  // inverse of those written before it, so it follows only the later ones, as in POV-Ray.
  // Shared by the copies of the object until one changes it.
  SharedOptional<PovTexture> texture;
  SourceLoc textureLoc;
  std::optional<PovInterior> interior;
  // interior_texture: the texture seen from inside, in the same space as `texture`.
  SharedOptional<PovTexture> interiorTexture;
  SourceLoc interiorTextureLoc;
  bool noShadow = false;
  bool noImage = false;       // no_image [on|off]
  bool noReflection = false;  // no_reflection [on|off]
  bool doubleIlluminate = false;
  bool inverse = false;
  // The object's `uv_mapping`: the textures given to it after it are read at (u, v, 0).
  bool uvMapping = false;
  // light_group: a group (kind Group) whose light sources light only its objects.
  bool lightGroup = false;
  bool globalLights = false;  // global_lights [on|off]
  // `hollow [on|off]` when written; unwritten, the object takes its CSG parent's (POV-Ray
  // sets the flag of the operands that did not set theirs), else not hollow.
  std::optional<bool> hollow;
  // clipped_by and bounded_by: objects in this object's own space (before `transform`,
  // which moves them with it); boundIsClip when one was written as the other
  // (clipped_by { bounded_by } or bounded_by { clipped_by }), POV-Ray's one list for both.
  std::vector<PovObject> clip;
  std::vector<PovObject> bound;
  bool boundIsClip = false;
  int depth = 1;       // levels of objects, this one included
  uint64_t nodes = 1;  // objects within, this one included
  // A blob's components' own textures, one per component once any has one (else empty),
  // each in the blob's own space (the component's transforms after it applied), with
  // where it was written.
  std::vector<std::optional<PovTexture>> componentTextures;
  std::vector<SourceLoc> componentTextureLocs;
};

// A light's looks_like: the object, moved to the light's centre as it was there (and by the
// modifiers written after it in looks_like's block), and the light's transform at that
// point; the light's later transforms move the object too.
struct PovLooksLike {
  PovObject object;
  PovTransform lightAt;
};

// The items the reader makes, for #declare and for identifiers in blocks. Each keeps the
// errors of the features Lucent cannot render that its declaration holds: they are
// reported where the item is used in the scene, not where an include declares it.
struct SceneItem : Item {
  std::vector<Diagnostic> refused;
};
struct ObjectItem : SceneItem {
  PovObject object;
  std::string_view kind() const override { return object.keyword; }
};
struct CameraItem : SceneItem {
  PovCamera camera;
  std::string_view kind() const override { return "camera"; }
};
struct PigmentItem : SceneItem {
  PovPigment pigment;
  std::string_view kind() const override { return "pigment"; }
};
struct FinishItem : SceneItem {
  PovFinish finish;
  std::string_view kind() const override { return "finish"; }
};
struct TextureItem : SceneItem {
  PovTexture texture;
  std::string_view kind() const override { return "texture"; }
};
struct InteriorItem : SceneItem {
  PovInterior interior;
  std::string_view kind() const override { return "interior"; }
};
// `material { texture { } interior { } }`: what it gives an object.
struct PovMaterial {
  std::optional<PovTexture> texture;
  std::optional<PovTexture> interiorTexture;
  std::optional<PovInterior> interior;
};
struct MaterialItem : SceneItem {
  PovMaterial material;
  std::string_view kind() const override { return "material"; }
};
struct NormalItem : SceneItem {
  PovNormal normal;
  std::string_view kind() const override { return "normal"; }
};
// `#declare M = pigment_map {...}`, used as `pigment_map { M }`.
struct PigmentMapItem : SceneItem {
  std::vector<TextureMapEntry> entries;
  std::string_view kind() const override { return "pigment_map"; }
};
struct ColorMapItem : SceneItem {
  std::vector<PovColorMapEntry> map;
  SourceLoc loc;
  std::string_view kind() const override { return "color_map"; }
};
// A declaration of something Lucent lacks or the reader does not read yet
// (`#declare M = pigment_map {...}`): its error waits for a use.
struct RefusedItem : SceneItem {
  std::string word;
  std::string_view kind() const override { return word; }
};
// `#declare S = sky_sphere {...}`, used as `sky_sphere { S ... }`.
struct SkySphereItem : SceneItem {
  PovSkySphere sky;
  std::string_view kind() const override { return "sky_sphere"; }
};
struct TransformItem : SceneItem {
  PovTransform transform;
  std::string_view kind() const override { return "transform"; }
};

// A pigment, read and resolved, as an entry of a map or a list: its plain colour, or its
// texture placed by its own transforms (read_maps.cpp).
TextureMapEntry entryOf(const PovPigment& p, double at);

// The refusal of a second texture { } (a layer), where it is.

class SceneReader : public ItemReader {
 public:
  SceneReader(Scene& scene, Diagnostics& diagnostics, const Options& options)
      : scene_(scene), diags_(diagnostics), options_(options) {}

  ItemPtr read(const Token& t, TokenStream& in) override;
  // read_pattern_functions.cpp
  ItemPtr patternPigment(TokenStream& in, bool noise) override;
  std::optional<double> pigmentValue(const FunctionValue& f, int member,
                                     const double* xyz) override;
  // object_geometry.cpp: an object item built for trace(), inside() and the extents.
  std::shared_ptr<const ObjectGeometry> geometry(const ItemPtr& item, TokenStream& in) override;

  // Reads the scene's top level to its end, placing each object, light and setting.
  void readScene(TokenStream& in);
  // The camera (POV-Ray's default when the scene has none), the settings and the lights
  // placed: the scene complete.
  void finishScene(TokenStream& in);

 private:
  // What an object's nodes inherit from its parent: the texture and interior, the matrix
  // (POV-Ray's space) from the parent's object space to the space the texture was placed
  // in, and the material the parent's node has, with the matrix it was placed by.
  struct Inherited {
    const PovTexture* texture = nullptr;
    const PovInterior* interior = nullptr;
    // The interior texture (interior_texture) and the material made of it for the parent,
    // placed as `material` is.
    const PovTexture* interiorTexture = nullptr;
    std::optional<uint32_t> interiorMaterial;
    Mat4 interiorTextureFromNode{1.0};
    Mat4 textureFromParent{1.0};
    std::optional<uint32_t> material;
    Mat4 materialTextureFromNode{1.0};
    bool hollow = false;  // the parent's hollow flag, which an operand without one takes
    // POV-Ray links this object to the frame as an object of its own: a top-level object,
    // or an operand of such a union without clip or bounds, which POV-Ray splits. Where
    // an object is, its bounds may be dropped (keepsBound).
    bool framed = false;
    // An enclosing object transforms this one after its own modifiers, which makes POV-Ray
    // recompute its box from its shape (addBoxCut).
    bool movedAfter = false;
  };

  // scene_reader.cpp: the top level, and what cannot be read
  std::shared_ptr<SceneItem> readItem(const Token& t, TokenStream& in);
  void readDefault(TokenStream& in);
  void place(const PovObject& object, TokenStream& in);
  std::unique_ptr<Node> toNode(const PovObject& o, const Inherited& inherited, bool topLevel,
                               TokenStream& in);
  static bool keepsBound(const PovObject& o, bool framed);
  void addBoxCut(const PovObject& o, const Inherited& here, Node& n, TokenStream& in);
  static void addBoundBox(const AABB& cut, const SourceLoc& at, Node& n);
  void addInteriorMaterial(const PovObject& o, Inherited& here, const Mat4& textureFromNode,
                           Node& n, TokenStream& in);
  void addComponentMaterials(const PovObject& o, const Inherited& here, Node& n, TokenStream& in);
  // `hollow`: the object's flag, which POV-Ray promotes to its interior (the material's).
  // uv: objectToTexture leads from the shape's (u, v, 0) (a uv-mapped map's entries).
  Material importLayer(const PovTexture& layer, const PovInterior& interior,
                       const Mat4& objectToTexture, const SourceLoc& at, TokenStream& in,
                       bool uv = false);
  uint32_t addMaterial(const PovTexture& texture, const PovInterior& interior, bool hollow,
                       const Mat4& textureFromNode, const SourceLoc& at, TokenStream& in);
  // The item an identifier names if it is a T; the errors its declaration kept are
  // reported (or, inside another declaration, kept by that one).
  template <class T>
  const T* use(const Token& t, TokenStream& in) {
    const auto* item = dynamic_cast<const T*>(itemOf(t));
    if (item) reportRefused(*item, t.loc(), in);
    return item;
  }
  void reportRefused(const SceneItem& item, const SourceLoc& usedAt, TokenStream& in);
  // A feature Lucent lacks, named in a block: its error kept, the block skipped to its
  // closing brace.
  void refuseInBlock(const Token& t, TokenStream& in, const std::string& why);
  // A keyword Lucent cannot render, or one the reader does not read yet: an error kept
  // (reading goes on), and the block that follows it skipped. In an object read for a
  // #declare (`object`), the error is kept with the object and said where it is placed.
  void unsupported(const Token& t, TokenStream& in, bool skipBlock, PovObject* object = nullptr);
  // The same inside a block: its error kept, and the block skipped to its closing brace.
  void unreadInBlock(const Token& t, TokenStream& in);
  void keepError(TokenStream& in, const SourceLoc& at, const std::string& message);
  // What Lucent cannot render, said at `at`: an error (kept with the include and macro
  // chain that led `here`, or plainly; inside a declaration kept by the item until it is
  // used), or with --skip-unsupported counted by kind and left out.
  void refusal(TokenStream& in, const SourceLoc& at, const std::string& message, bool here);
  void warn(TokenStream& in, const SourceLoc& at, const std::string& message);

  // read_objects.cpp
  bool isObjectKeyword(const Token& t) const;
  bool startsObject(const Token& t);
  PovObject readObjectOrCopy(const Token& t, TokenStream& in);
  PovObject readObject(const Token& t, TokenStream& in);
  void readShape(PovObject& o, TokenStream& in);
  void readIsosurface(PovObject& o, TokenStream& in);  // read_isosurface.cpp
  void readObjectModifiers(PovObject& o, TokenStream& in, std::string_view written = {});
  void promoteFinishIor(PovObject& o);
  void readChildren(PovObject& o, TokenStream& in);
  void readLightGroup(PovObject& o, TokenStream& in);
  bool readObjectModifier(const Token& t, PovObject& o, TokenStream& in);
  void readClipOrBound(const Token& t, PovObject& o, TokenStream& in);
  bool readTransform(const Token& t, TokenStream& in, PovTransform& m);
  PovTransform readTransformBlock(TokenStream& in);

  // read_shapes.cpp: the shapes' parameters (readShape), each one's block
  void refuse(PovObject& o, const SourceLoc& at, TokenStream& in, const std::string& message);
  void refuseShape(PovObject& o, const SourceLoc& at, TokenStream& in, const std::string& message);
  void readQuadric(PovObject& o, TokenStream& in);
  void readPoly(PovObject& o, TokenStream& in);
  void readBlob(PovObject& o, TokenStream& in);
  void readLatheOrSor(PovObject& o, TokenStream& in);
  void readPrism(PovObject& o, TokenStream& in);
  void readPolygon(PovObject& o, TokenStream& in);
  void readBicubicPatch(PovObject& o, TokenStream& in);
  void readJuliaFractal(PovObject& o, TokenStream& in);
  void readSphereSweep(PovObject& o, TokenStream& in);
  void readOvus(PovObject& o, TokenStream& in);
  void readParametric(PovObject& o, TokenStream& in);  // read_parametric.cpp
  void readText(PovObject& o, TokenStream& in);
  void readHeightFieldOptions(HeightFieldSpec& s, TokenStream& in);
  void readFunctionHeightField(PovObject& o, TokenStream& in);
  void readHeightField(PovObject& o, TokenStream& in);
  void readMesh(PovObject& o, TokenStream& in);
  void readMesh2(PovObject& o, TokenStream& in);
  bool readMeshTriangleExtras(PovObject& o, TokenStream& in, std::optional<std::array<Vec2, 3>>& uv,
                              MeshBuild& b, int& texture);
  void readFaceIndices(TokenStream& in, size_t textures, std::vector<std::array<long, 3>>& faces,
                       std::vector<int>& faceTextures, std::optional<SourceLoc>& perCorner);
  void finishMeshShape(PovObject& o, TokenStream& in, const MeshBuild& b, bool insideVector);
  void splitByTexture(PovObject& o, TokenStream& in, const MeshBuild& b, bool insideVector);

  // read_textures.cpp
  PovNormal readNormal(TokenStream& in, const PovNormal* start);
  // The camera's normal on the imported camera, placed in POV-Ray's space (its image point
  // (x0, y0, 0) is the same in both spaces; the ray's direction is carried by the mirror).
  void importCameraNormal(const PovCamera& camera, Camera& imported, TokenStream& in);
  PovPigment readPigment(TokenStream& in, const PovPigment& start);
  // A pigment's or a normal's keywords up to the '}' of its block, or (inEntry) up to the
  // ']' of a map's entry; both read. An entry's colours keep their filter and transmit.
  PovPigment readPigmentBody(TokenStream& in, const PovPigment& start, bool inEntry);
  PovNormal readNormalBody(TokenStream& in, const PovNormal* start, bool inEntry);
  PovFinish readFinish(TokenStream& in, const PovFinish& start);
  PovTexture readTexture(TokenStream& in, const PovTexture& start);
  // A texture's body up to `closing` ("}", or "]" in a texture_map), the opening read.
  PovTexture readTextureBody(TokenStream& in, const PovTexture& start, std::string_view closing);
  // `PATTERN modifiers texture_map { [v T] ... }` or `checker texture { } texture { }` in a
  // texture, from its pattern keyword `t` on: the map, or nothing (an error was kept).
  bool readTextureMap(const Token& t, TokenStream& in, PovTexture& tex);
  // `layered(under, top)` where POV-Ray allows it: neither may be a pattern of textures
  // (POV-Ray's "Cannot layer over a patterned texture"), an error kept at `at` otherwise.
  PovTexture layerOver(PovTexture under, PovTexture top, const SourceLoc& at, TokenStream& in);
  // `function { F }` of a function pattern (the keyword read): F as Lucent expression text of
  // x, y and z in POV-Ray's space, compiled once per text. Null, with an error kept, for a
  // function Lucent cannot evaluate.
  std::shared_ptr<const PatternFunction> readPatternFunction(TokenStream& in);
  std::shared_ptr<const TextureMapEntry> readPatternPigment(TokenStream& in);
  // F's Lucent expression text with its parameters named `names`, its compiled field
  // (compiled once per text) and the pigments it calls (pigment functions, placed in
  // POV-Ray's space); nullopt, with an error kept naming `what`, for a function Lucent
  // cannot evaluate. The text's free names are `variables`: x, y, z, or a parametric's u, v.
  std::optional<FunctionInput> compiledFunction(
      const FunctionValue& f, const std::vector<std::string>& names, const char* what,
      TokenStream& in, const std::vector<std::string>& variables = {"x", "y", "z"});
  // The pigment functions of a function's text (read_isosurface.cpp): each pigment as a
  // texture placed in POV-Ray's space, with the component the call takes.
  std::vector<std::shared_ptr<const PigmentFunction>> pigmentFunctions(
      const std::vector<PigmentCall>& calls, TokenStream& in);
  // A texture (one layer, layers or a map) as a Lucent material, placed.
  Material importTexture(const PovTexture& texture, const PovInterior& interior,
                         const Mat4& objectToTexture, const SourceLoc& at, TokenStream& in,
                         bool uv = false);
  void readUvTexture(const Token& t, TokenStream& in, PovTexture& tex, std::string_view closing);
  void readTextureIdentifiers(TokenStream& in, PovTexture& tex);
  void readRefraction(const Token& t, TokenStream& in);
  void mapAtUv(PovTexture& tex, bool bendInWorld);
  void placeUvNormal(const PovNormal& normal, const Mat4& objectToTexture, NormalSpec& spec,
                     const SourceLoc& at, TokenStream& in);
  void readTiles(const Token& t, TokenStream& in, PovTexture& tex);
  PovInterior readInterior(TokenStream& in, const PovInterior& start);
  PovMaterial readMaterial(TokenStream& in);
  void readReflection(TokenStream& in, PovReflection& r);

  // read_camera_light.cpp
  PovCamera readCamera(TokenStream& in);
  // mesh_camera { ... } (the keyword read) into c.
  void readMeshCamera(const Token& t, TokenStream& in, PovCamera& c);
  PovLight readLight(const SourceLoc& loc, TokenStream& in);
  void readGlobalSettings(TokenStream& in);
  void readBackground(TokenStream& in);

  // read_atmosphere.cpp
  void readFog(const SourceLoc& loc, TokenStream& in);
  void readRainbow(const SourceLoc& loc, TokenStream& in);
  void readSkySphere(const SourceLoc& loc, TokenStream& in);
  // `{ [Identifier] pigment {...}... transforms }` after `sky_sphere`.
  PovSkySphere readSkySphereBlock(const SourceLoc& loc, TokenStream& in);

  // read_patterns.cpp: patterns, their colours and modifiers
  bool readPatternKeyword(const Token& t, TokenStream& in, PovPigment& p);
  bool readPigmentModifier(const Token& t, TokenStream& in, PovPigment& p);
  bool readPatternModifier(const Token& t, TokenStream& in, PatternSpec* spec,
                           PatternPlacement* placement);
  void readFractalColouring(const Token& t, TokenStream& in, PatternSpec& s);
  std::vector<PovColorMapEntry> readColorMap(TokenStream& in, SourceLoc& loc);
  void resolvePigmentColours(PovPigment& p, TokenStream& in, bool nested = false);
  // read_image_map.cpp: `image_map { [TYPE] "file" modifiers }` as a projected <image>
  void readImageMap(const Token& t, TokenStream& in, PovPigment& p);
  void readImageAlpha(const Token& t, bool transmitAll, TokenStream& in, ImageTexture& image);
  void readPaletteEntry(const Token& k, bool transmit, TokenStream& in, ImageTexture& image);
  void readBumpMap(const Token& t, TokenStream& in, PovNormal& n);
  // An image file as image_map, bump_map, image_pattern and material_map name it.
  struct ImageFileSpec {
    std::string path;
    std::string format;               // POV-Ray's type keyword, else the file's extension
    std::optional<GammaCurve> gamma;  // the `gamma` written after the name, if any
    SourceLoc gammaLoc;
  };
  ImageFileSpec readImageFileSpec(TokenStream& in);
  // The file of an image whose values are read as stored (POV-Ray reads a bump map's, an
  // image pattern's and a material map's without gamma unless one is written).
  std::string readStoredImageFile(TokenStream& in);
  std::shared_ptr<const ImagePattern> readImagePattern(TokenStream& in);
  void readMaterialMap(const Token& t, TokenStream& in, PovTexture& tex);
  // read_object_pattern.cpp: `object { OBJECT transforms` of an object pattern (the keyword
  // read; its list and '}' are the caller's), the object a node of the scene's <defs>.
  std::shared_ptr<const ObjectPattern> readObjectPatternObject(const Token& t, TokenStream& in);
  // `object { OBJECT transforms COLOUR, COLOUR }` or `... pigment {..} pigment {..} }` in a
  // pigment, and `... normal {..} normal {..} }` in a normal (the keyword read).
  void readObjectPigment(const Token& t, TokenStream& in, PovPigment& p);
  void readObjectNormal(const Token& t, TokenStream& in, PovNormal& n);
  // read_maps.cpp: `normal {..} [,] normal {..}`, up to `count`, into n's map.
  void readNormalList(TokenStream& in, PovNormal& n, size_t count);
  // The pattern of an object pattern, placed as `was` is.
  static PatternTexture objectPatternTexture(std::shared_ptr<const ObjectPattern> object,
                                             const Texture& was);
  // read_maps.cpp: maps and lists of pigments, averages of pigments and of normals
  std::vector<TextureMapEntry> readPigmentMap(TokenStream& in, const Token& at,
                                              bool average = false);
  bool readPigmentMapKeyword(const Token& t, TokenStream& in, PovPigment& p);
  bool readBlockPigments(TokenStream& in, PovPigment& p, size_t count);
  void refuseNestedImage(const TextureMapEntry& e, TokenStream& in);
  bool readNormalMapKeyword(const Token& t, TokenStream& in, PovNormal& n);
  std::vector<SlopeMapEntry> readSlopeMap(TokenStream& in, const Token& at);
  bool readBlockNormal(const Token& t, TokenStream& in, PovNormal& n);
  void skipEntryRest(const Token& t, TokenStream& in);
  bool refusePattern(const Token& t, TokenStream& in, bool inEntry = false);
  bool readOldNormal(const Token& t, TokenStream& in, PovTexture& tex);
  bool isTexturePattern(const Token& t) const;
  static bool isLackingPattern(const Token& t);
  // `warp { ... }`: a step of the placement after the transforms written before it
  // (sdl/read_warps.cpp); false when t is not `warp`.
  bool readWarp(const Token& t, TokenStream& in, PatternPlacement* placement,
                PovTransform& transform);

  PovTexture defaultTexture() const {
    return {defaults_.pigment, defaults_.normal, defaults_.finish, {}, 0, false, {}, {}, {}};
  }

  Scene& scene_;
  Diagnostics& diags_;
  const Options& options_;
  PovDefaults defaults_;
  std::optional<PovCamera> camera_;  // the last camera read (POV-Ray renders with it)
  PovGlobalSettings global_;
  SourceLoc globalLoc_;
  PovBackground background_;
  std::set<std::string> warned_;  // each warning said once per place
  int objectDepth_ = 0;           // objects being read within each other
  // The errors kept by the declarations being read (innermost last): a feature Lucent
  // cannot render is an error only where the declared item is used.
  std::vector<std::vector<Diagnostic>> declaring_;
  std::set<std::string> refusalsReported_;    // each declared refusal reported once
  std::shared_ptr<TextureItem> lastTexture_;  // the texture declared just now, if any
  // --skip-unsupported: each kind of feature left out, with its count and first place.
  struct Skipped {
    int count = 0;
    SourceLoc first;
    std::string message;
  };
  std::map<std::string, Skipped> skipped_;
  // The isosurface fields compiled so far, by their function's text (read_isosurface.cpp).
  // The fields compiled so far (isosurfaces and function patterns), by expression text.
  std::map<std::string, std::shared_ptr<const ScalarField>> compiledFields_;
  // Every pigment function's pigment, whose patterns take the scene's noise generator at
  // the end (finishScene).
  std::vector<std::shared_ptr<PigmentFunction>> pigmentFunctions_;
  // The pigments of pigment and pattern functions evaluated while the scene is read, by
  // function (read_pattern_functions.cpp).
  std::map<const FunctionValue*, std::shared_ptr<PigmentFunction>> evaluatedPigments_;
  // The text outlines laid out so far, by font, string and offset (read_shapes.cpp).
  std::map<std::string, std::shared_ptr<TextOutline>> textOutlines_;
  // The material of the objects that take the default texture (unpatterned) as it is now.
  std::optional<uint32_t> defaultMaterial_;
  // The materials of declared textures used as they are, by declaration, interior and
  // (for a patterned one) the placement of its pattern: the objects that give it the same
  // share one material, named after an unpatterned texture.
  struct DeclaredUse {
    uint64_t declaration;
    double ior, fadeDistance, fadePower;
    float fadeR, fadeG, fadeB;
    bool hollow;
    std::array<double, 16> placement;  // zero for an unpatterned texture
    bool operator<(const DeclaredUse& o) const {
      return std::tie(declaration, ior, fadeDistance, fadePower, fadeR, fadeG, fadeB, hollow,
                      placement) < std::tie(o.declaration, o.ior, o.fadeDistance, o.fadePower,
                                            o.fadeR, o.fadeG, o.fadeB, o.hollow, o.placement);
    }
  };
  std::map<DeclaredUse, uint32_t> declaredMaterials_;
  std::map<std::string, int> namedMaterialCount_;  // named materials by texture name
  uint64_t declarations_ = 0;                      // #declare'd textures and materials so far
  // Errors and warnings issued so far: a declared texture whose import said something is
  // imported again at each use, so that each place is told.
  uint64_t notesIssued_ = 0;
  // Unnamed materials equal in every term share one index (a loop's objects of one colour).
  MaterialSharing sharedMaterials_;
  // CSG of objects that are not solids, rewritten as POV-Ray keeps their surfaces.
  OpenOperands openOperands_;
  // Object patterns' objects put into the scene's <defs> so far (their ids' numbers).
  int objectPatterns_ = 0;
  // The objects built for trace() and the like, each with its item (few in a scene: a
  // search of this list is fast enough).
  std::vector<std::pair<ItemPtr, std::shared_ptr<const ObjectGeometry>>> built_;
  // Each level takes several frames of the C++ stack (more under the sanitizers, which the
  // fuzzer found overflowing at 1000 through #declare inside skipped blocks); POV-Ray's own
  // macro depth is 100.
  static constexpr int kMaxObjectDepth = 256;
  // Shapes, CSG and lights within one object (a scene may hold many such objects).
  static constexpr uint64_t kMaxObjectNodes = 10'000'000;
};

// What loading a POV-Ray scene gives: the scene, or null with the errors; warnings go to
// Options::output as the core's do.
struct SceneLoad {
  std::unique_ptr<Scene> scene;
  Diagnostics diagnostics;
};

// Reads the POV-Ray scene at `path` (its image size from options.imageWidth and
// imageHeight, which the camera's framing depends on).
SceneLoad loadScene(const std::filesystem::path& path, const Options& options);
// The same for `text`, named `name`, lying in `folder` (for tests).
SceneLoad loadSceneText(const std::string& name, const std::string& text,
                        const std::filesystem::path& folder, const Options& options);

}  // namespace lucent::sdl
