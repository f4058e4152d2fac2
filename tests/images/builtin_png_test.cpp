// The built-in PNG and PPM writers (images/builtin/) against OpenImageIO's: the same scene
// or pixels written both ways decode, through OpenImageIO, to the same values, bit depth
// and colour space, and carry the same chunks; and the built-in read-back check refuses
// what is not complete.
#include "../temp_dir.h"
#include "app/image_output.h"
#include "images/builtin/builtin_images.h"
#include "images/image_plugin.h"
#include "lang/parser.h"
#include "render/renderer.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

using namespace lucent;
namespace fs = std::filesystem;
using lucent::test::TempDir;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void spit(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Every chunk of a PNG file but the compressed pixels (IDAT, whose bytes depend on the
// zlib settings), as type + data: IHDR (size, bit depth, colour type), gAMA, sRGB, cHRM,
// oFFs, tEXt, IEND.
std::vector<std::string> metadataChunks(const std::string& path) {
  const std::string png = slurp(path);
  REQUIRE(png.size() > 8);
  REQUIRE(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  std::vector<std::string> chunks;
  for (size_t at = 8; at + 12 <= png.size();) {
    const auto byte = [&](size_t i) { return static_cast<uint32_t>(static_cast<uint8_t>(png[i])); };
    const uint32_t length = byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
    REQUIRE(at + 12 + length <= png.size());
    std::string chunk = png.substr(at + 4, 4 + length);
    if (chunk.compare(0, 4, "IDAT") != 0) chunks.push_back(chunk);
    at += 12 + length;
  }
  return chunks;
}

bool hasChunk(const std::vector<std::string>& chunks, const std::string& type) {
  for (const std::string& c : chunks)
    if (c.compare(0, 4, type) == 0) return true;
  return false;
}

struct Decoded {
  ImageHeader header;
  std::vector<float> values;
};

// Through OpenImageIO (the plugin), whoever wrote the file.
Decoded decodeWithOiio(const std::string& path) {
  std::string error;
  std::unique_ptr<ImageReader> in = imagePlugin().openFile(path, error);
  INFO(path << ": " << error);
  REQUIRE(in);
  Decoded d;
  d.header = in->header();
  d.values.resize(static_cast<size_t>(d.header.width) * d.header.height * d.header.channels);
  REQUIRE(in->readPixels(d.values.data()).empty());
  return d;
}

// The two files decode to the same header and every channel value.
void requireSameImage(const std::string& builtin, const std::string& plugin) {
  const Decoded a = decodeWithOiio(builtin);
  const Decoded b = decodeWithOiio(plugin);
  CHECK(a.header.width == b.header.width);
  CHECK(a.header.height == b.header.height);
  CHECK(a.header.channels == b.header.channels);
  CHECK(a.header.eightBit == b.header.eightBit);
  CHECK(a.header.sixteenBit == b.header.sixteenBit);
  CHECK(a.header.floating == b.header.floating);
  CHECK(a.header.alphaChannel == b.header.alphaChannel);
  CHECK(a.header.colorSpace == b.header.colorSpace);
  REQUIRE(a.values.size() == b.values.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.values.size(); ++i)
    if (a.values[i] != b.values[i]) ++differing;
  CHECK(differing == 0);
}

const char* kScene = R"(<scene version="1">
  <render width="64" height="48"/>
  <camera position="0 1 5" look-at="0 0 0"/>
  <light position="5 5 5"/>
  <material id="red" diffuse="1 0.2 0.1" specular="0.5" shininess="40"/>
  <plane normal="0 1 0" offset="-1">
    <material diffuse="1"><checker color1="1" color2="0.2"/></material>
  </plane>
  <sphere radius="1" material="red"/>
</scene>)";

Image renderScene() {
  ParseResult parsed = parseSceneString(kScene, "builtin.xml");
  REQUIRE(parsed.scene);
  World world(*parsed.scene);
  return Renderer(world, parsed.scene->cameras[0]).render().image;
}

// Code values covering the whole range, both bytes of a 16-bit word differing.
std::vector<uint16_t> rampWords(size_t n) {
  std::vector<uint16_t> words(n);
  for (size_t i = 0; i < n; ++i) words[i] = static_cast<uint16_t>((i * 40503u + 1u) % 65536u);
  words[0] = 0;
  words[n - 1] = 65535;
  return words;
}

}  // namespace

TEST_CASE("a render written as PNG by the built-in writer and by OpenImageIO decodes the same",
          "[images][builtin]") {
  TempDir dir("builtin");
  const Image image = renderScene();
  writeImageFile(image, dir.file("builtin.png"));
  writeImageFile(image, dir.file("plugin.png"), ImageWriter::Plugin);
  requireSameImage(dir.file("builtin.png"), dir.file("plugin.png"));

  const Decoded d = decodeWithOiio(dir.file("builtin.png"));
  CHECK(d.header.eightBit);
  CHECK(d.header.channels == 3);
  CHECK(d.header.saysSrgb());
  // A real picture, not a blank one: the lit sphere and the checker give many values.
  CHECK(std::count(d.values.begin(), d.values.end(), d.values[0]) <
        static_cast<long>(d.values.size() / 2));

  const std::vector<std::string> chunks = metadataChunks(dir.file("builtin.png"));
  CHECK(chunks == metadataChunks(dir.file("plugin.png")));
  CHECK(hasChunk(chunks, "sRGB"));
  CHECK(hasChunk(chunks, "gAMA"));
  CHECK(hasChunk(chunks, "cHRM"));
}

TEST_CASE("a render written as PPM by the built-in writer is OpenImageIO's file byte for byte",
          "[images][builtin]") {
  TempDir dir("builtin");
  const Image image = renderScene();
  writeImageFile(image, dir.file("builtin.ppm"));
  writeImageFile(image, dir.file("plugin.ppm"), ImageWriter::Plugin);
  const std::string bytes = slurp(dir.file("builtin.ppm"));
  CHECK(bytes.compare(0, 13, "P6\n64 48\n255\n") == 0);
  CHECK(bytes.size() == 13 + 64 * 48 * 3);
  CHECK(bytes == slurp(dir.file("plugin.ppm")));
  requireSameImage(dir.file("builtin.ppm"), dir.file("plugin.ppm"));
}

TEST_CASE("8- and 16-bit, sRGB and linear, grey and RGB PNGs: built-in and OpenImageIO agree",
          "[images][builtin]") {
  TempDir dir("builtin");
  const int width = 37, height = 11;  // odd sizes: no row padding hides a stride error
  for (StoredType type : {StoredType::UInt8, StoredType::UInt16})
    for (const char* space : {"sRGB", "Linear"})
      for (int channels : {1, 3}) {
        const bool sixteen = type == StoredType::UInt16;
        INFO((sixteen ? "16" : "8") << "-bit " << space << ", " << channels << " channels");
        const size_t n = static_cast<size_t>(width) * height * channels;
        std::vector<uint16_t> words = rampWords(n);
        std::vector<uint8_t> bytes(n);
        for (size_t i = 0; i < n; ++i) bytes[i] = static_cast<uint8_t>(words[i] >> 8);
        ImageToWrite image;
        image.format = "png";
        image.width = width;
        image.height = height;
        image.channels = channels;
        image.type = type;
        image.colorSpace = space;
        image.pixels = sixteen ? static_cast<const void*>(words.data()) : bytes.data();
        REQUIRE(builtinWrites(image));
        REQUIRE_FALSE(builtinWriteFile(dir.file("builtin.png"), image));
        REQUIRE_FALSE(imagePlugin().writeFile(dir.file("plugin.png"), image));
        CHECK(builtinReadsBackComplete(dir.file("builtin.png"), image));
        requireSameImage(dir.file("builtin.png"), dir.file("plugin.png"));
        CHECK(metadataChunks(dir.file("builtin.png")) == metadataChunks(dir.file("plugin.png")));

        // The stored values themselves (so that agreeing on a wrong byte order fails too).
        const Decoded d = decodeWithOiio(dir.file("builtin.png"));
        CHECK(d.header.sixteenBit == sixteen);
        CHECK(d.header.colorSpace == space);
        const float scale = sixteen ? 65535.0f : 255.0f;
        size_t wrong = 0;
        for (size_t i = 0; i < n; ++i)
          if (d.values[i] * scale - (sixteen ? words[i] : bytes[i]) > 0.01f ||
              (sixteen ? words[i] : bytes[i]) - d.values[i] * scale > 0.01f)
            ++wrong;
        CHECK(wrong == 0);
      }
}

TEST_CASE("the built-in writers leave the rest to OpenImageIO", "[images][builtin]") {
  ImageToWrite image;
  image.format = "png";
  image.colorSpace = "sRGB";
  CHECK(builtinWrites(image));
  image.channels = 4;  // alpha: OpenImageIO's writer un-premultiplies
  CHECK_FALSE(builtinWrites(image));
  image.channels = 3;
  image.type = StoredType::Float;
  CHECK_FALSE(builtinWrites(image));
  image.type = StoredType::UInt8;
  image.colorSpace = "";
  CHECK_FALSE(builtinWrites(image));
  image.format = "pnm";
  image.pnmBinary = true;
  CHECK(builtinWrites(image));
  image.pnmBinary = false;  // text PPM
  CHECK_FALSE(builtinWrites(image));
  image.format = "tiff";
  image.colorSpace = "sRGB";
  CHECK_FALSE(builtinWrites(image));
}

TEST_CASE("the built-in read-back check refuses a truncated or damaged file", "[images][builtin]") {
  TempDir dir("builtin");
  const Image image = renderScene();
  std::vector<uint8_t> bytes(image.pixels.size() * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      bytes[3 * i + c] = static_cast<uint8_t>(srgbByte(image.pixels[i][c]));
  ImageToWrite file;
  file.width = image.width;
  file.height = image.height;
  file.colorSpace = "sRGB";
  file.pixels = bytes.data();

  for (const char* format : {"png", "pnm"}) {
    INFO(format);
    file.format = format;
    file.pnmBinary = file.format == "pnm";
    const std::string path = dir.file(std::string("a.") + format);
    REQUIRE_FALSE(builtinWriteFile(path, file));
    REQUIRE(builtinReadsBackComplete(path, file));
    const std::string whole = slurp(path);

    spit(path, whole.substr(0, whole.size() / 2));
    CHECK_FALSE(builtinReadsBackComplete(path, file));
    spit(path, whole.substr(0, whole.size() - 1));  // PNG: the end chunk's checksum
    CHECK_FALSE(builtinReadsBackComplete(path, file));
    spit(path, "");
    CHECK_FALSE(builtinReadsBackComplete(path, file));
    ImageToWrite other = file;
    other.width += 1;  // a complete file of another size
    spit(path, whole);
    CHECK_FALSE(builtinReadsBackComplete(path, other));
  }
  // PNG: one flipped byte in the compressed pixels breaks IDAT's checksum.
  const std::string path = dir.file("a.png");
  file.format = "png";
  REQUIRE_FALSE(builtinWriteFile(path, file));
  std::string damaged = slurp(path);
  const size_t idat = damaged.find("IDAT");
  REQUIRE(idat != std::string::npos);
  damaged[idat + 10] = static_cast<char>(damaged[idat + 10] ^ 0x55);
  spit(path, damaged);
  CHECK_FALSE(builtinReadsBackComplete(path, file));
  // PPM: a byte too many.
  file.format = "pnm";
  file.pnmBinary = true;
  REQUIRE_FALSE(builtinWriteFile(dir.file("a.ppm"), file));
  spit(dir.file("a.ppm"), slurp(dir.file("a.ppm")) + "x");
  CHECK_FALSE(builtinReadsBackComplete(dir.file("a.ppm"), file));
}

TEST_CASE("a built-in write that fails says at which step and why", "[images][builtin]") {
  TempDir dir("builtin");
  std::vector<uint8_t> bytes(4 * 3 * 3, 128);
  ImageToWrite file;
  file.width = 4;
  file.height = 3;
  file.colorSpace = "sRGB";
  file.pixels = bytes.data();
  for (const char* format : {"png", "pnm"}) {
    INFO(format);
    file.format = format;
    file.pnmBinary = file.format == "pnm";
    WriteFailure missing = builtinWriteFile(dir.file("no/such/folder/a.png"), file);
    CHECK(missing.step == WriteFailure::Create);
    CHECK(missing.reason == "No such file or directory");
    // /dev/full accepts the open and refuses the data.
    WriteFailure full = builtinWriteFile("/dev/full", file);
    CHECK(full.step == WriteFailure::Write);
    CHECK_THAT(full.reason, Catch::Contains("No space left on device"));
  }
}
