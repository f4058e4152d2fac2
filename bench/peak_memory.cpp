// Peak memory of a whole `lucent render` run: writes a scene with one displaced-sphere
// mesh of about N triangles (a binary PLY file beside it), runs the given lucent binary on
// it and reports the child's peak resident memory (getrusage's ru_maxrss) and its time,
// beside the same figures for `lucent --version`: what the process costs before any scene.
//
//   peak_memory LUCENT_BINARY WORK_DIR [--triangles N] [--size W]
#include "bench_util.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>

using namespace lucent;
using namespace lucent::bench;

namespace {

void writePly(const std::string& path, const MeshData& m) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\n"
      << "element vertex " << m.positions.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "element face " << m.triangles.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : m.positions) {
    float f[3] = {float(p.x), float(p.y), float(p.z)};
    out.write(reinterpret_cast<const char*>(f), sizeof f);
  }
  for (const auto& t : m.triangles) {
    unsigned char three = 3;
    int32_t idx[3] = {int32_t(t[0]), int32_t(t[1]), int32_t(t[2])};
    out.write(reinterpret_cast<const char*>(&three), 1);
    out.write(reinterpret_cast<const char*>(idx), sizeof idx);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr, "usage: peak_memory LUCENT_BINARY WORK_DIR [--triangles N] [--size W]\n");
    return 2;
  }
  std::string lucent = argv[1], dir = argv[2];
  size_t triangles = 1000000;
  int size = 640;
  for (int i = 3; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--triangles") triangles = std::stoul(argv[i + 1]);
    else if (a == "--size") size = std::stoi(argv[i + 1]);
    else throw std::invalid_argument("unknown option " + a);
  }

  MeshData mesh = displacedSphereOf(triangles);
  writePly(dir + "/bumpy.ply", mesh);
  std::ofstream(dir + "/bumpy.xml")
      << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<scene version=\"1\">\n"
      << "  <render width=\"" << size << "\" height=\"" << size << "\" samples=\"1\"/>\n"
      << "  <camera position=\"0.6 0.9 3.2\" look-at=\"0 0 0\" fov=\"40\"/>\n"
      << "  <light type=\"point\" position=\"4 6 5\"/>\n"
      << "  <mesh src=\"bumpy.ply\" smooth=\"false\"/>\n"
      << "</scene>\n";
  size_t written = mesh.triangles.size();
  mesh = MeshData();  // this process's memory is not the child's, but keep it small

  // The process alone (`lucent --version`: its shared libraries and static data), then
  // the render.
  struct Run { bool ok; double seconds, peakMB; };
  auto run = [&](std::vector<std::string> args) {
    auto t0 = Clock::now();
    pid_t pid = fork();
    if (pid == 0) {
      std::vector<char*> argv{const_cast<char*>(lucent.c_str())};
      for (auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      int devnull = open("/dev/null", O_WRONLY);
      dup2(devnull, 1);
      execv(lucent.c_str(), argv.data());
      std::perror("exec");
      _exit(127);
    }
    int status = 0;
    struct rusage usage;
    std::memset(&usage, 0, sizeof usage);
    wait4(pid, &status, 0, &usage);
    return Run{WIFEXITED(status) && WEXITSTATUS(status) == 0, secondsSince(t0),
               usage.ru_maxrss / 1024.0};
  };
  Run base = run({"--version"});
  Run render = run({"render", dir + "/bumpy.xml", "-o", dir + "/bumpy.png", "-q"});
  fmt::print("# peak_memory: lucent render of {} triangles at {}x{}; {}, load {}\n", written,
             size, size, cpuModel(), loadAverage());
  fmt::print("\n| run | exit | wall time | peak memory |\n|---|---|---|---|\n");
  fmt::print("| `lucent --version` (the process alone) | {} | {:.1f} s | {:.0f} MB |\n",
             base.ok ? "0" : "FAILED", base.seconds, base.peakMB);
  fmt::print("| `lucent render`, {} triangles, {}x{} | {} | {:.1f} s | {:.0f} MB |\n", written,
             size, size, render.ok ? "0" : "FAILED", render.seconds, render.peakMB);
  fmt::print("| the scene's share (difference) | | | {:.0f} MB |\n", render.peakMB - base.peakMB);
  bool ok = render.ok;
  return ok ? 0 : 1;
}
