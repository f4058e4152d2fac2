// lucent compare SCENE -o DIR: renders the scene with Lucent (through the render library)
// and with POV-Ray (the exported scene, --pov FILE, or a POV-Ray scene itself) at the same size,
// sampling, depth and bail-out, both as 16-bit linear PNGs, and writes into DIR:
//   lucent.png, povray.png            8-bit sRGB renders to look at
//   lucent-linear16.png, povray-linear16.png   what the metrics read
//   diff.png                          heat map of the largest channel difference
//   scene.pov, povray.log             the exported scene and POV-Ray's messages
//   report.json, report.html
// and prints PSNR, SSIM, RMSE, the maximum difference and the share of pixels off by more
// than 2/255 (on sRGB-encoded values).
//
// Exit statuses: 1 wrong usage; 2 an invalid scene or one that cannot be exported; 3 no
// povray (with how to install it), a POV-Ray failure, a --pov scene whose assumed_gamma
// cannot be read (its images could not be read back), or files that cannot be written.
// The metrics never change the status: comparing is a measurement.
#include "commands.h"

#include "frame_loading.h"
#include "load_pov_scene.h"
#include "load_scene.h"

#include "povray/compare_report.h"
#include "povray/image_compare.h"
#include "povray/pov_export.h"
#include "povray/pov_gamma.h"
#include "povray/pov_runner.h"
#include "render/renderer.h"

#include <fmt/core.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace lucent::cli {

namespace fs = std::filesystem;

namespace {

constexpr double kThreshold = 2.0 / 255.0;
constexpr double kHeatMapScale = 16.0 / 255.0;

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out.flush()) throw std::runtime_error(fmt::format("cannot write '{}'", path.string()));
}

RgbImage toRgb(const Image& image) {
  RgbImage out(image.width, image.height);
  for (size_t p = 0; p < image.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) out.rgb[p * 3 + c] = image.pixels[p][c];
  return out;
}

// The last lines of POV-Ray's log, where its error is.
std::string logTail(const fs::path& log, size_t lines) {
  std::ifstream in(log);
  std::vector<std::string> all;
  for (std::string line; std::getline(in, line);) all.push_back(line);
  std::string out;
  for (size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i)
    out += "  " + all[i] + "\n";
  return out;
}

// A hand-written scene without `#version 3.7` is read with the 3.62 rules, which change
// transparency and gamma.
std::vector<std::string> checkHandWritten(const std::string& path, const std::string& text,
                                          const PovAssumedGamma& gamma) {
  std::vector<std::string> notes;
  if (text.find("#version") == std::string::npos)
    notes.push_back(path +
                    ": no #version directive: POV-Ray reads it with 3.62 rules "
                    "(transparency and gamma differ); start it with `#version 3.7;`");
  if (gamma.kind == PovAssumedGamma::Kind::Absent)
    notes.push_back(path +
                    ": no assumed_gamma: put `global_settings { assumed_gamma 1.0 }` "
                    "so colours are linear as in Lucent");
  if (gamma.nonLinear())
    notes.push_back(fmt::format(
        "{}:{}: assumed_gamma {}: POV-Ray computes with the scene's numbers as they are and "
        "writes them as {}-encoded values; compared its working values (File_Gamma={}) with "
        "Lucent's linear ones, which holds where the Lucent scene has the same numbers (image "
        "maps and srgb colours are decoded by POV-Ray and would differ)",
        path, gamma.line, gamma.fileGamma(),
        gamma.kind == PovAssumedGamma::Kind::Srgb ? "sRGB" : "gamma-" + gamma.fileGamma(),
        gamma.fileGamma()));
  return notes;
}

// The scene request of compare's options, checked.
SceneRequest compareRequest(const CompareOptions& options) {
  SceneRequest request = sceneRequestOf(options);
  // -s is checked here, not applied by loadScene: compare's default is 1, not the scene's.
  checkOverrides(request);
  request.samples.reset();
  return request;
}

// One sample per pixel unless asked: both renderers then trace the pixel centres, the only
// sampling they share exactly. Or corner sampling, which is POV-Ray's method 2 exactly,
// unless -s asks for samples. Returns whether corner sampling is kept.
bool chooseSampling(RenderSettings& settings, const CompareOptions& options) {
  const bool corners = settings.adaptiveMode == AdaptiveMode::Corners && !options.samples;
  if (!corners) {
    settings.samples = options.samples.value_or(1);
    settings.adaptive = 0.0;
    settings.adaptiveMode = AdaptiveMode::Centres;
  }
  return corners;
}

// The report's settings and file names, before anything is rendered.
CompareReport startReport(const CompareOptions& options, const RenderSettings& settings) {
  CompareReport report;
  report.scene = options.scene;
  report.width = settings.width;
  report.height = settings.height;
  report.samples = settings.samples;
  report.maxDepth = settings.maxDepth;
  report.minWeight = settings.minWeight;
  report.heatMapScale = kHeatMapScale;
  report.lucentImage = "lucent.png";
  report.povrayImage = "povray.png";
  report.lucentLinear = "lucent-linear16.png";
  report.povrayLinear = "povray-linear16.png";
  report.heatMap = "diff.png";
  report.povrayLog = "povray.log";
  if (settings.samples > 1)
    report.warnings.push_back(fmt::format(
        "{} samples per pixel: Lucent uses Halton offsets, POV-Ray an antialiasing grid; "
        "expect differences at edges",
        settings.samples));
  return report;
}

// The POV-Ray scene compared with.
struct PovScene {
  fs::path path;
  std::string fileGamma = "1.0";  // the working gamma its images are read back with
};

// The scene exported beside the results; none when it cannot be exported (said why).
std::optional<PovScene> exportedScene(const Scene& scene, const CompareOptions& options,
                                      const fs::path& dir, CompareReport& report) {
  PovExport exported = exportPov(scene, PovExportOptions{options.camera});
  for (const PovIssue& issue : exported.issues) {
    fmt::print(stderr, "{}\n", issue.str());
    report.warnings.push_back(issue.str());
  }
  if (!exported.ok()) {
    fmt::print(stderr, "{}: cannot be exported to POV-Ray; nothing compared\n", options.scene);
    return std::nullopt;
  }
  PovScene pov{fs::absolute(dir / "scene.pov")};
  writeText(pov.path, exported.text);
  // POV-Ray writes its working values, as Lucent's image holds them before the output.
  const WorkingGamma& gamma = scene.render.workingGamma;
  if (gamma.srgb) pov.fileGamma = "sRGB";
  else if (!gamma.linear()) pov.fileGamma = fmt::format("{}", gamma.power);
  return pov;
}

// --pov FILE: the user's own scene, its working gamma read from it.
PovScene handWrittenScene(const CompareOptions& options, CompareReport& report) {
  PovScene pov{fs::absolute(options.povFile)};
  report.handWritten = true;
  std::ifstream in(options.povFile);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const PovAssumedGamma gamma = findAssumedGamma(text);
  if (gamma.kind == PovAssumedGamma::Kind::Unreadable)
    throw IoFailure(
        fmt::format("--pov {}: {}: POV-Ray's output depends on its working gamma, "
                    "which compare must know to read the image back; write "
                    "`assumed_gamma` with a number (or srgb) in global_settings",
                    options.povFile, gamma.problem));
  pov.fileGamma = gamma.fileGamma();
  for (const std::string& note : checkHandWritten(options.povFile, text, gamma)) {
    fmt::print(stderr, "lucent: warning: {}\n", note);
    report.warnings.push_back(note);
  }
  return pov;
}

// `compare SCENE.pov`: POV-Ray renders the scene file itself, given what Lucent's import
// was given (-D as Declare=, the library folders as +L, the INI file's animation with only
// the compared frame rendered), its working gamma read from the file as for --pov.
PovScene sceneItself(const CompareOptions& options, const CommonOptions& common, const Scene& scene,
                     PovrayRender& job) {
  PovScene pov{fs::absolute(options.scene)};
  std::ifstream in(options.scene);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const PovAssumedGamma gamma = findAssumedGamma(text);
  if (gamma.kind != PovAssumedGamma::Kind::Unreadable) pov.fileGamma = gamma.fileGamma();
  // An assumed_gamma the file's own text does not hold (in an include, or an expression)
  // is the import's: a gamma power is told apart from the sRGB working gamma an older scene
  // without one takes (whose values POV-Ray writes as they are, read back as 1.0).
  const WorkingGamma& evaluated = scene.render.workingGamma;
  if (gamma.kind != PovAssumedGamma::Kind::Number && gamma.kind != PovAssumedGamma::Kind::Srgb &&
      !evaluated.srgb && !evaluated.linear())
    pov.fileGamma = fmt::format("{}", evaluated.power);
  for (const auto& [name, value] : common.defines)
    if (name != "clock" && name != "frame") job.extra.push_back("Declare=" + name + "=" + value);
  const sdl::PovIni ini = readIniOption(common);
  for (const std::string& dir : common.povLibrary)
    job.extra.push_back(povrayPathOption("+L", fs::absolute(dir).string()));
  for (const fs::path& dir : ini.library)
    job.extra.push_back(povrayPathOption("+L", fs::absolute(dir).string()));
  for (const auto& [name, value] : ini.declared)
    if (!common.defines.count(name)) job.extra.push_back(fmt::format("Declare={}={}", name, value));
  const Animation& a = scene.animation;
  if (a.present && !common.defines.count("clock")) {
    const int first = ini.initialFrame.value_or(1);
    const int frame = first + scene.frame - 1;
    job.extra.insert(
        job.extra.end(),
        {fmt::format("+KFI{}", first), fmt::format("+KFF{}", first + a.frames - 1),
         fmt::format("+KI{}", a.clockFrom), fmt::format("+KF{}", a.clockTo),
         a.cyclic ? "+KC" : "-KC", fmt::format("+SF{}", frame), fmt::format("+EF{}", frame)});
    job.clock = 0.0;  // POV-Ray works it out from the frame, as Lucent did
  }
  return pov;
}

// POV-Ray names the image of an animation's frame with the frame's number before the
// extension: the newest image of that name in the folder.
fs::path writtenImage(const fs::path& output) {
  if (fs::exists(output)) return output;
  const std::string stem = output.stem().string();
  fs::path found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(output.parent_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(stem, 0) != 0 || entry.path().extension() != output.extension()) continue;
    const std::string digits = entry.path().stem().string().substr(stem.size());
    if (!digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos)
      found = entry.path();
  }
  return found;
}

// Lucent, through the render library. Writes its 16-bit linear image into `dir`.
void renderLucent(const Scene& scene, const Camera& camera, const CompareOptions& options,
                  const fs::path& dir, CompareReport& report) {
  World world(scene);
  Renderer renderer(world, camera);
  RenderControl control;
  control.threads = options.threads.value_or(0);
  RenderResult lucent = renderer.render(control);
  report.lucentRender = "render library (Renderer::render)";
  report.lucentSeconds = lucent.seconds;
  writeLinear16Png(toRgb(lucent.image), (dir / report.lucentLinear).string());
}

// POV-Ray, in the folder of its scene so that relative file names resolve as its author
// meant. Returns the image it wrote.
fs::path renderPovray(const std::string& povray, const PovScene& pov,
                      const RenderSettings& settings, PovrayRender job, bool corners,
                      const CompareOptions& options, const fs::path& dir, CompareReport& report) {
  job.input = pov.path.string();
  job.output = fs::absolute(dir / report.povrayLinear).string();
  job.width = settings.width;
  job.height = settings.height;
  job.samples = settings.samples;
  job.corners = corners;
  job.cornerThreshold = settings.adaptive;
  job.cornerDepth = settings.adaptiveDepth;
  job.threads = options.threads.value_or(0);
  job.fileGamma = pov.fileGamma;
  std::vector<std::string> args = povrayArguments(job);
  report.povrayCommand = commandLine(povray, args);
  const fs::path log = fs::absolute(dir / report.povrayLog);
  std::error_code ec;
  fs::remove(log, ec);
  fs::remove(job.output, ec);
  ProcessResult run = runProcess(povray, args, pov.path.parent_path().string(), log.string());
  report.povraySeconds = run.seconds;
  const fs::path written = writtenImage(job.output);
  if (!run.started || run.exitStatus != 0 || written.empty())
    throw IoFailure(
        fmt::format("POV-Ray failed (exit status {}) on '{}'; its last messages "
                    "({}):\n{}",
                    run.exitStatus, pov.path.string(), log.string(), logTail(log, 12)));
  return written;
}

// Both images decoded the same way: 16-bit linear code values, then sRGB-encoded for the
// metrics and the pictures; the metrics, pictures and reports into `dir`.
void writeComparison(const fs::path& dir, const fs::path& povrayLinear, CompareReport& report) {
  RgbImage lucentImage = srgbEncoded(readLinear16Png((dir / report.lucentLinear).string()));
  RgbImage povImage = srgbEncoded(readLinear16Png(povrayLinear.string()));
  if (povImage.width != lucentImage.width || povImage.height != lucentImage.height)
    throw IoFailure(fmt::format("POV-Ray wrote a {}x{} image, Lucent {}x{}", povImage.width,
                                povImage.height, lucentImage.width, lucentImage.height));
  report.metrics = compareImages(lucentImage, povImage, kThreshold);
  writeDisplayPng(lucentImage, (dir / report.lucentImage).string());
  writeDisplayPng(povImage, (dir / report.povrayImage).string());
  writeDisplayPng(differenceHeatMap(lucentImage, povImage, kHeatMapScale),
                  (dir / report.heatMap).string());
  writeText(dir / "report.json", reportJson(report));
  writeText(dir / "report.html", reportHtml(report));
}

void printMetrics(const CompareReport& report, const fs::path& dir) {
  const ImageMetrics& m = report.metrics;
  fmt::print("psnr:       {}\n",
             std::isfinite(m.psnr) ? fmt::format("{:.2f} dB", m.psnr) : "inf (identical)");
  fmt::print("ssim:       {:.6f}\n", m.ssim);
  fmt::print("rmse:       {:.6g}\n", m.rmse);
  fmt::print("max diff:   {:.6g} at pixel ({}, {})\n", m.maxDiff, m.maxX, m.maxY);
  fmt::print("over 2/255: {:.3f} % of pixels ({})\n", 100.0 * m.shareOver, m.pixelsOver);
  fmt::print("time:       lucent {:.3f} s, povray {:.3f} s\n", report.lucentSeconds,
             report.povraySeconds);
  fmt::print("report:     {}\n", (dir / "report.html").string());
}

}  // namespace

int runCompare(const CompareOptions& options, const CommonOptions& common) {
  const SceneRequest request = compareRequest(options);
  std::optional<std::string> povray = findPovray();
  if (!povray) throw IoFailure(povrayInstallHint());
  if (!options.povFile.empty() && !fs::is_regular_file(options.povFile))
    throw IoFailure(fmt::format("--pov {}: no such file", options.povFile));

  LoadedScene loaded = loadOneFrame(request, common, options.frame);
  const Scene& scene = *loaded.scene;
  RenderSettings& settings = loaded.scene->render;
  const bool corners = chooseSampling(settings, options);

  const fs::path dir(options.outputDir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw IoFailure(fmt::format("cannot create the folder '{}'", dir.string()));

  CompareReport report = startReport(options, settings);
  PovrayRender job;
  job.clock = scene.clock;
  std::optional<PovScene> pov;
  if (!options.povFile.empty()) pov = handWrittenScene(options, report);
  else if (isPovScene(options.scene, common.format)) {
    pov = sceneItself(options, common, scene, job);
    report.handWritten = true;  // not an export: the POV-Ray scene as written
  } else pov = exportedScene(scene, options, dir, report);
  if (!pov) return kInvalidScene;
  report.povScene = pov->path.string();

  // --threads bounds every parallel step, the BVH builds too.
  std::optional<tbb::global_control> threadLimit;
  if (options.threads.value_or(0) > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<size_t>(*options.threads));
  renderLucent(scene, *loaded.camera, options, dir, report);
  const fs::path povrayLinear =
      renderPovray(*povray, *pov, settings, job, corners, options, dir, report);
  writeComparison(dir, povrayLinear, report);
  printMetrics(report, dir);
  return kOk;
}

}  // namespace lucent::cli
