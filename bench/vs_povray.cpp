// Whole-process time and peak memory of Lucent against POV-Ray 3.7 on the same scenes,
// one thread each: the displaced-sphere mesh of about N triangles (binary PLY file) and a
// field of a thousand spheres on a checkered ground. The POV-Ray scenes are the
// exports of the Lucent ones (`lucent export-pov`), so both renderers load, build and
// trace the same geometry; POV-Ray reads the mesh as an inline mesh2 (it has no PLY
// reader), which is the form POV-Ray users hold large meshes in.
//
//   vs_povray LUCENT_BINARY WORK_DIR [--triangles N] [--spheres N] [--size W] [--repeat R]
//             [--povray PATH] [--tsv FILE]
//
// Each run is the whole process: start, parse, load, build, render, write the PNG, exit.
// The run with the best wall time of R counts (the machine is shared), with its CPU
// time; the peak memory is the largest ru_maxrss of the R runs.
#include "bench_scenes.h"
#include "child_process.h"

#include <algorithm>

using namespace lucent;
using namespace lucent::bench;

namespace {

ChildRun bestOfRuns(int repeat, const std::string& program, const std::vector<std::string>& args) {
  ChildRun best;
  best.seconds = 1e300;
  double peak = 0.0;
  for (int i = 0; i < repeat; ++i) {
    ChildRun r = runChild(program, args, /*keepStderr=*/false);
    if (!r.ok) return r;
    peak = std::max(peak, r.peakMB);
    if (r.seconds < best.seconds) best = r;
  }
  best.peakMB = peak;
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr,
               "usage: vs_povray LUCENT_BINARY WORK_DIR [--triangles N] [--spheres N] "
               "[--size W] [--repeat R] [--povray PATH] [--tsv FILE]\n");
    return 2;
  }
  std::string lucent = argv[1], dir = argv[2], povray = "/usr/bin/povray", tsvPath;
  size_t triangles = 1000000;
  int spheres = 1000, size = 640, repeat = 3;
  for (int i = 3; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--triangles") triangles = std::stoul(argv[i + 1]);
    else if (a == "--spheres") spheres = std::stoi(argv[i + 1]);
    else if (a == "--size") size = std::stoi(argv[i + 1]);
    else if (a == "--repeat") repeat = std::max(1, std::stoi(argv[i + 1]));
    else if (a == "--povray") povray = argv[i + 1];
    else if (a == "--tsv") tsvPath = argv[i + 1];
    else throw std::invalid_argument("unknown option " + a);
  }
  const int width = size, height = size * 3 / 4;

  size_t written = writeMeshScene(dir, triangles, size);
  writeSphereField(dir, spheres, width, height);
  fmt::print(
      "# vs_povray: {} triangles at {}x{}, {} spheres at {}x{}, one thread, best of {}; "
      "{}, load {}\n",
      written, size, size, spheres, width, height, repeat, cpuModel(), loadAverage());

  struct Scene {
    std::string name, label;
    int w, h;
  };
  const Scene scenes[] = {
      {"bumpy", fmt::format("mesh, {} triangles, {}x{}", written, size, size), size, size},
      {"spheres", fmt::format("{} spheres, {}x{}", spheres, width, height), width, height}};

  // Wall time is what a user waits; CPU time (user + system, of the process alone) is
  // what the process itself costs, and the fairer figure when other work shares the
  // cores (on an idle machine the two agree for one thread).
  TsvFile tsv(tsvPath);
  tsv.row(
      "# scene\tlucent_s\tlucent_cpu_s\tlucent_MB\tpovray_s\tpovray_cpu_s\tpovray_MB\t"
      "speedup_wall\tspeedup_cpu");
  fmt::print(
      "\n| scene | Lucent wall | Lucent CPU | Lucent peak memory | POV-Ray wall "
      "| POV-Ray CPU | POV-Ray peak memory | POV-Ray / Lucent (wall) "
      "| POV-Ray / Lucent (CPU) |\n|---|---|---|---|---|---|---|---|---|\n");
  bool ok = true;
  for (const Scene& s : scenes) {
    const std::string xml = dir + "/" + s.name + ".xml", pov = dir + "/" + s.name + ".pov";
    ChildRun exported = runChild(lucent, {"export-pov", xml, "-o", pov}, false);
    ChildRun l = bestOfRuns(
        repeat, lucent,
        {"render", xml, "-o", dir + "/" + s.name + "-lucent.png", "-q", "--threads", "1"});
    // POV-Ray's own defaults for the rest (no anti-aliasing, as Lucent's one sample);
    // -D: no display window, +WT1: one render thread.
    ChildRun p;
    if (exported.ok)
      p = bestOfRuns(
          repeat, povray,
          {"+I" + pov, "+O" + dir + "/" + s.name + "-povray.png", fmt::format("+W{}", s.w),
           fmt::format("+H{}", s.h), "-D", "-V", "-GA", "+WT1", "-A"});
    auto cell = [](const ChildRun& r, double v, const char* f) {
      return r.ok ? fmt::format(fmt::runtime(f), v) : std::string("FAILED");
    };
    auto ratio = [&](double a, double b) {
      return l.ok && p.ok ? fmt::format("{:.2f}×", a / b) : std::string("n/a");
    };
    fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", s.label,
               cell(l, l.seconds, "{:.2f} s"), cell(l, l.cpuSeconds, "{:.2f} s"),
               cell(l, l.peakMB, "{:.0f} MB"), cell(p, p.seconds, "{:.2f} s"),
               cell(p, p.cpuSeconds, "{:.2f} s"), cell(p, p.peakMB, "{:.0f} MB"),
               ratio(p.seconds, l.seconds), ratio(p.cpuSeconds, l.cpuSeconds));
    if (l.ok && p.ok)
      tsv.row("{}\t{:.3f}\t{:.3f}\t{:.1f}\t{:.3f}\t{:.3f}\t{:.1f}\t{:.3f}\t{:.3f}", s.name,
              l.seconds, l.cpuSeconds, l.peakMB, p.seconds, p.cpuSeconds, p.peakMB,
              p.seconds / l.seconds, p.cpuSeconds / l.cpuSeconds);
    ok = ok && l.ok && p.ok;
  }
  return ok ? 0 : 1;
}
