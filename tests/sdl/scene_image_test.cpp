// POV-Ray scenes read by the scene reader and rendered by Lucent, held to POV-Ray's own
// image of the same file with the gallery's bounds (tests/data/sdl/scenes).
#include "pov_meaning_support.h"
#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "lang/parser.h"
#include "lang/scene_writer.h"
#include "sdl/scene_reader.h"

using namespace lucent;
using namespace lucent::test;

namespace {

std::string fileText(const std::filesystem::path& path) {
  std::ifstream in(path);
  REQUIRE(in);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void requireSameImageAsPovray(const std::string& name, int width, int height) {
  const std::filesystem::path path = sdltest::dataFolder() / "scenes" / name;
  sdl::CollectedOutput out;
  sdl::Options options;
  options.imageWidth = width;
  options.imageHeight = height;
  options.output = &out;
  sdl::SceneLoad load = sdl::loadScene(path, options);
  for (const Diagnostic& d : load.diagnostics.all()) UNSCOPED_INFO(d.str());
  for (const std::string& w : out.warnings) UNSCOPED_INFO(w);
  REQUIRE(load.scene);
  requireSameImage(*load.scene, fileText(path));
}

// The scene converted to XML (lucent convert's writer) reads back and renders to the same
// pixels: written as if beside the .pov file, so that the files it names are read.
void requireConvertKeepsPixels(const std::string& name, int width, int height) {
  const std::filesystem::path path = sdltest::dataFolder() / "scenes" / name;
  sdl::Options options;
  options.imageWidth = width;
  options.imageHeight = height;
  const sdl::SceneLoad load = sdl::loadScene(path, options);
  REQUIRE(load.scene);
  WriteOptions write;
  write.folder = path.parent_path().string();
  const std::string xml = writeSceneXml(*load.scene, write);
  const ParseResult again = parseSceneString(xml, (path.parent_path() / "converted.xml").string());
  for (const Diagnostic& d : again.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(again.scene);
  const RgbImage a = renderWithLucent(*load.scene), b = renderWithLucent(*again.scene);
  CHECK(a.rgb == b.rgb);
}

// The same, with POV-Ray rendering the scene file where it lies, as a user would: for a
// scene that reads a file beside it (a height field's image).
void requireSameImageAsPovrayInPlace(const std::string& name, int width, int height) {
  const std::filesystem::path path = sdltest::dataFolder() / "scenes" / name;
  sdl::CollectedOutput out;
  sdl::Options options;
  options.imageWidth = width;
  options.imageHeight = height;
  options.output = &out;
  sdl::SceneLoad load = sdl::loadScene(path, options);
  for (const Diagnostic& d : load.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(load.scene);
  const auto povray = findPovray();
  REQUIRE(povray);
  TempDir dir("sdl-image");
  PovrayRender job;
  job.input = path.string();
  job.output = dir.file("povray.png");
  job.width = width;
  job.height = height;
  job.threads = 1;
  const std::string log = dir.file("log.txt");
  ProcessResult run = runProcess(*povray, povrayArguments(job), path.parent_path().string(), log);
  INFO(fileText(log));
  REQUIRE(run.exitStatus == 0);
  const RgbImage lucent = srgbEncoded(renderWithLucent(*load.scene));
  const RgbImage pov = srgbEncoded(readLinear16Png(job.output));
  const ImageMetrics m = compareImages(lucent, pov, 2.0 / 255.0);
  INFO("PSNR " << m.psnr << " dB, SSIM " << m.ssim << ", " << 100.0 * m.shareOver
               << " % of pixels off by more than 2/255");
  CHECK(m.psnr >= 40.0);
  CHECK(m.ssim >= 0.99);
  CHECK(m.shareOver <= 0.01);
}

// The same for a scene whose two renders differ by sampling noise (focal blur: POV-Ray's
// hexagonal lens grid and jitter table against Lucent's scrambled Sobol points), held to
// a PSNR and SSIM measured for it instead of the 2/255 share.
void requireNearImageAsPovray(const std::string& name, int width, int height, double minPsnr,
                              double minSsim) {
  const std::filesystem::path path = sdltest::dataFolder() / "scenes" / name;
  sdl::Options options;
  options.imageWidth = width;
  options.imageHeight = height;
  sdl::SceneLoad load = sdl::loadScene(path, options);
  for (const Diagnostic& d : load.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(load.scene);
  const RgbImage lucent = srgbEncoded(renderWithLucent(*load.scene));
  const RgbImage povray = srgbEncoded(renderWithPovray(fileText(path), width, height));
  const ImageMetrics m = compareImages(lucent, povray, 2.0 / 255.0);
  INFO("PSNR " << m.psnr << " dB, SSIM " << m.ssim);
  CHECK(m.psnr >= minPsnr);
  CHECK(m.ssim >= minSsim);
}

}  // namespace

TEST_CASE("scene reader image: a sphere on a plane as POV-Ray users write it",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("sphere_on_plane.pov", 160, 120);
}

TEST_CASE("scene reader image: clipped_by and bounded_by as POV-Ray applies them",
          "[sdl][scene][image][povray][clip]") {
  requireSameImageAsPovray("clip_and_bound.pov", 160, 120);
}

TEST_CASE("scene reader image: CSG, declared objects, #default and a loop",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("csg_and_objects.pov", 160, 120);
}

TEST_CASE("scene reader image: a macro's objects in a loop, a spotlight and a sky_sphere",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("macro_ring.pov", 160, 120);
}

TEST_CASE("scene reader image: isosurfaces of user functions and functions.inc's closed forms",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("isosurface_functions.pov", 160, 120);
}

TEST_CASE("scene reader image: quadrics of shapes_old.inc, a quadric and a quartic",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("quadrics_and_polys.pov", 160, 120);
}

TEST_CASE("scene reader image: a lathe, a sor, prisms and a blob", "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("lathe_sor_prism_blob.pov", 160, 120);
}

TEST_CASE("scene reader image: a text, a superellipsoid, a mesh and a mesh2",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("text_and_mesh.pov", 160, 120);
}

TEST_CASE("scene reader image: height fields, their image's rows where POV-Ray puts them",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovrayInPlace("height_field.pov", 160, 120);
}

TEST_CASE("scene reader image: height fields of functions, sampled as POV-Ray samples them",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("height_field_function.pov", 160, 120);
}

TEST_CASE("scene reader image: textures placed among transforms, block patterns and maps",
          "[sdl][scene][image][povray][texture]") {
  requireSameImageAsPovray("textures_placed.pov", 160, 120);
}

TEST_CASE("scene reader image: noise patterns with turbulence and colour maps, normals",
          "[sdl][scene][image][povray][texture]") {
  requireSameImageAsPovray("noise_patterns.pov", 160, 120);
}

TEST_CASE("scene reader image: image maps projected planar, spherical, cylindrical and torus",
          "[sdl][scene][image][povray][image-map]") {
  requireSameImageAsPovrayInPlace("image_maps.pov", 160, 120);
}

TEST_CASE("scene reader image: material maps picked by palette index and red, palette bump maps",
          "[sdl][scene][image][povray][material-map]") {
  requireSameImageAsPovrayInPlace("material_maps.pov", 360, 360);
}

TEST_CASE("scene reader image: normal maps, lists of normals, slope maps and #default normals",
          "[sdl][scene][image][povray][texture]") {
  requireSameImageAsPovray("normal_maps.pov", 160, 120);
}

TEST_CASE("scene reader image: the 27 tilings from above, each pixel the tiling's value",
          "[sdl][scene][image][tiling]") {
  requireSameImageAsPovray("tilings.pov", 270, 90);
}

TEST_CASE("scene reader image: tilings as normals, bent by their slope",
          "[sdl][scene][image][tiling]") {
  requireSameImageAsPovray("tilings_normal.pov", 160, 80);
}

TEST_CASE("scene reader image: pavements as a pigment and as normals",
          "[sdl][scene][image][pavement]") {
  requireSameImageAsPovray("pavements.pov", 240, 80);
}

TEST_CASE(
    "scene reader image: object patterns in a pigment, a pigment list, a normal and a texture",
    "[sdl][scene][image][object]") {
  requireSameImageAsPovray("object_patterns.pov", 240, 160);
}

TEST_CASE("scene reader image: uv_mapping of pigments, textures and texture maps on meshes",
          "[sdl][scene][image][povray][texture][uv-mapping]") {
  requireSameImageAsPovray("uv_mapping.pov", 160, 120);
}

TEST_CASE(
    "scene reader image: uv_mapping on spheres, boxes, tori, lathes, sors, patches and "
    "shapes without (u,v)",
    "[sdl][scene][image][povray][texture][uv-mapping]") {
  requireSameImageAsPovrayInPlace("uv_mapping_shapes.pov", 240, 180);
}

TEST_CASE("scene reader image: a bicubic patch's uv_vectors",
          "[sdl][scene][image][povray][uv-mapping]") {
  requireSameImageAsPovrayInPlace("bicubic_uv_vectors.pov", 240, 180);
}

TEST_CASE("scene reader image: lights projected through objects",
          "[sdl][scene][image][povray][projected-through]") {
  requireSameImageAsPovray("projected_through.pov", 240, 180);
}

TEST_CASE("scene reader image: rainbows", "[sdl][scene][image][povray][rainbow]") {
  requireSameImageAsPovray("rainbow.pov", 240, 180);
}

TEST_CASE(
    "scene reader image: GIFs in image maps, material maps, bump maps, image patterns and "
    "height fields",
    "[sdl][scene][image][povray][gif]") {
  // Palette images read through giflib: a transparent index, an entry's own transmit, the
  // indices of material maps and height fields (make_gif_maps.py writes the files).
  requireSameImageAsPovrayInPlace("gif_maps.pov", 240, 180);
  requireConvertKeepsPixels("gif_maps.pov", 120, 90);
}

TEST_CASE("scene reader image: planes whose normal is not unit keep their distance",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("plane_normal_length.pov", 160, 120);  // 20 dB when divided
}

TEST_CASE("scene reader image: mesh triangles with textures of their own",
          "[sdl][scene][image][povray][mesh]") {
  // Each texture's triangles are a mesh of their own in Lucent (a union): POV-Ray's image,
  // and the XML `convert` writes renders the same pixels.
  requireSameImageAsPovray("mesh_textures.pov", 240, 180);
  requireConvertKeepsPixels("mesh_textures.pov", 120, 90);
}

TEST_CASE("scene reader image: blob components with textures of their own, and ovuses",
          "[sdl][scene][image][povray][blob][ovus]") {
  requireSameImageAsPovray("blob_component_textures.pov", 240, 180);
  requireSameImageAsPovray("ovus.pov", 240, 180);
}

TEST_CASE("scene reader image: fog through the gap of a clipped solid",
          "[sdl][scene][image][povray][fog][clip]") {
  requireSameImageAsPovray("clipped_fog.pov", 240, 180);
}

TEST_CASE("scene reader image: CSG with operands that have no inside, as POV-Ray keeps them",
          "[sdl][scene][image][povray][csg]") {
  requireSameImageAsPovray("csg_open_operands.pov", 240, 180);
  // Written by convert as valid XML (unions of the solids' operation and clipped open
  // operands) that renders to the same pixels.
  requireConvertKeepsPixels("csg_open_operands.pov", 120, 90);
}

TEST_CASE("scene reader image: CSG with discs inside below their plane as in POV-Ray",
          "[sdl][scene][image][povray][csg][disc]") {
  requireSameImageAsPovray("csg_discs.pov", 240, 180);
  requireSameImageAsPovray("csg_discs_inverse.pov", 240, 180);
  // convert writes them as valid XML (unions of clipped pieces, planes for the discs'
  // half-spaces, the box POV-Ray bounds them by) that renders to the same pixels.
  requireConvertKeepsPixels("csg_discs.pov", 120, 90);
}

TEST_CASE("scene reader image: assumed_gamma 2.2, a negative light and transmit -1 as POV-Ray's",
          "[sdl][scene][image][povray][gamma]") {
  // POV-Ray's own output (linear light) against what lucent render writes.
  requireSameImageAsPovrayInPlace("working_gamma.pov", 240, 180);
}

TEST_CASE("scene reader image: image maps decoded by format, chunks and gamma as POV-Ray's",
          "[sdl][scene][image][povray][image-map][gamma]") {
  // A PNG from sRGB or by its gAMA or sRGB chunk, a PPM as stored, an image's own gamma
  // over the file's, encoded into assumed_gamma 1.5; then a 3.6 scene's, which reads
  // files without a chunk as stored.
  requireSameImageAsPovrayInPlace("image_gamma.pov", 340, 120);
  requireSameImageAsPovrayInPlace("image_gamma_36.pov", 340, 120);
  // convert writes each image's gamma: the same pixels read back.
  requireConvertKeepsPixels("image_gamma.pov", 170, 60);
}

TEST_CASE("scene reader image: filter and transmit above 1, the surface subtracting its colour",
          "[sdl][scene][image][povray][transmit]") {
  requireSameImageAsPovray("transmit_above_one.pov", 240, 180);
  // convert writes the negative ambient, diffuse and emission as they are: the same pixels
  // read back.
  requireConvertKeepsPixels("transmit_above_one.pov", 120, 90);
}

TEST_CASE("scene reader image: mesh cameras of each distribution as POV-Ray's",
          "[sdl][scene][image][povray][camera][mesh-camera]") {
  // 0: two screens averaged, the rays started off the faces; 1: a mesh2 and a mesh counted
  // on, reversed, with a maximum distance; 2: a stereo pair; 3: uvs and smooth normals.
  for (const char* name :
       {"mesh_camera_d0.pov", "mesh_camera_d1.pov", "mesh_camera_d2.pov", "mesh_camera_d3.pov"}) {
    INFO(name);
    requireSameImageAsPovray(name, 48, 36);
  }
  // convert writes the faces as they are (inline <mesh> children of the camera): the same
  // pixels read back.
  requireConvertKeepsPixels("mesh_camera_d1.pov", 48, 36);
}

TEST_CASE("scene reader image: parametric surfaces", "[sdl][scene][image][povray][parametric]") {
  requireSameImageAsPovray("parametric.pov", 240, 180);
}

TEST_CASE("scene reader image: functions.inc's f_helix1 in isosurfaces",
          "[sdl][scene][image][povray][function]") {
  requireSameImageAsPovray("helix1_isosurface.pov", 240, 180);
}

TEST_CASE("scene reader image: image maps as entries of pigment maps and block patterns' lists",
          "[sdl][scene][image][povray][texture][image-map][pigment-map]") {
  requireSameImageAsPovrayInPlace("image_maps_in_maps.pov", 240, 180);
}

TEST_CASE("scene reader image: tiles, a checker of layered textures",
          "[sdl][scene][image][povray][texture][tiles]") {
  requireSameImageAsPovray("tiles.pov", 160, 120);
}

TEST_CASE("scene reader image: quaternion julia fractals, z² and z³ and a tilted slice",
          "[sdl][scene][image][povray][julia]") {
  requireSameImageAsPovray("julia_quaternion.pov", 160, 120);
}

TEST_CASE("scene reader image: hypercomplex julia fractals, z² and POV-Ray's cube",
          "[sdl][scene][image][povray][julia]") {
  requireSameImageAsPovray("julia_hypercomplex.pov", 160, 120);
}

TEST_CASE("scene reader image: palette entries' own filter and transmit in image maps",
          "[sdl][scene][image][povray][image-map][palette]") {
  requireSameImageAsPovrayInPlace("image_map_palette.pov", 240, 160);
}

TEST_CASE("scene reader image: uv-mapped normals bent where POV-Ray bends them",
          "[sdl][scene][image][povray][texture][uv-mapping][normal]") {
  requireSameImageAsPovray("uv_mapping_normals.pov", 240, 180);
}

TEST_CASE("scene reader image: uv-mapped entries of pigment maps and lists read (u, v, 0)",
          "[sdl][scene][image][povray][texture][uv-mapping][pigment-map]") {
  requireSameImageAsPovray("uv_mapping_entries.pov", 240, 180);
}

TEST_CASE("scene reader image: the object pattern on a box's face, counted inside as POV-Ray's",
          "[sdl][scene][image][povray][object]") {
  requireSameImageAsPovray("object_pattern_box_face.pov", 160, 120);
}

// 300 rays a pixel, every one taken (variance 0): both renderers converge on the same blur,
// and what is left is their sampling noise (measured 42.5 and 38.8 dB; a focus a tenth too
// far falls to 33.9 and 29.5 dB, a lens twice too wide to 26.0 and 24.6).
TEST_CASE("scene reader image: focal blur focused on a point",
          "[sdl][scene][image][povray][focal-blur]") {
  requireNearImageAsPovray("focal_blur.pov", 120, 90, 40.0, 0.98);
}

TEST_CASE("scene reader image: focal blur focused at the direction's length",
          "[sdl][scene][image][povray][focal-blur]") {
  requireNearImageAsPovray("focal_blur_default_focus.pov", 120, 90, 36.0, 0.94);
}

TEST_CASE("scene reader image: image maps with an alpha channel and a palette's tRNS",
          "[sdl][scene][image][povray][image-map][alpha]") {
  requireSameImageAsPovrayInPlace("image_map_alpha.pov", 400, 80);
}

TEST_CASE("scene reader image: an isosurface of f_noise3d lit from the camera has no black speck",
          "[sdl][scene][image][function][isosurface]") {
  // language/trace2.pov's terrain, lit only from the camera, with no ambient light: every
  // point the camera sees is lit unless a shadow ray finds the surface it leaves. Made of
  // the pattern's single-precision colour the function was bumpy at 1e-8, and 1 % of the
  // terrain's pixels were black.
  auto r = sdltest::readScene(R"(#version 3.7;
#include "functions.inc"
camera { location <3, 4, -5> right x*image_width/image_height look_at <0, 0, 0> angle 24 }
light_source { <3, 4, -5> color rgb 1 }
background { rgb 1 }
isosurface {
  function { y + f_noise3d(x, y, z) }
  max_gradient 1.75
  contained_by { box { <-1.1, -1, -1.1>, <1.1, 1, 1.1> } }
  translate y*0.75
  pigment { rgb 1 } finish { ambient 0 diffuse 1 }
}
)");
  REQUIRE(r->load.scene);
  const RgbImage image = renderWithLucent(*r->load.scene);
  int dark = 0, lit = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.at(x, y);
      if (p[0] < 0.999f) ++lit;  // the terrain (the background is white)
      if (p[0] <= 0.0f) ++dark;
    }
  CHECK(lit > 5000);
  CHECK(dark == 0);
}
