// volcomp-fw-linux: the board application as a Linux process (CANopen node + CiA 402 CSP gateway
// between two SocketCAN interfaces). See docs/linux-board.md.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "volcomp/hal/linux/gpiod_backend.hpp"
#include "volcomp/linux_board/config_file.hpp"
#include "volcomp/linux_board/linux_runner.hpp"

namespace {

const char kUsage[] =
    "usage: volcomp-fw-linux --config FILE [options]\n"
    "  --config FILE      configuration file (docs/linux-board.md)\n"
    "  --check-config     check the file, print the effective configuration and exit\n"
    "  --ready-file FILE  write the process id to FILE once running\n"
    "  --stats FILE       write statistics (frames, per-frame forwarding latency) as JSON at exit\n"
    "  --duration S       stop after S seconds (default: run until SIGINT/SIGTERM)\n"
    "  --no-latency       do not time forwarded frames\n"
    "  --version          print the version and the GPIO backends of this build\n";

}  // namespace

int main(int argc, char** argv) {
  std::string config_path;
  bool check = false;
  volcomp::linux_board::RunOptions run;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "volcomp-fw-linux: %s needs a value\n%s", a.c_str(), kUsage);
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--config") {
      config_path = value();
    } else if (a == "--check-config") {
      check = true;
    } else if (a == "--ready-file") {
      run.ready_file = value();
    } else if (a == "--stats") {
      run.stats_file = value();
    } else if (a == "--duration") {
      const std::string v = value();
      char* end = nullptr;
      run.duration_s = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || run.duration_s < 0) {
        std::fprintf(stderr, "volcomp-fw-linux: bad --duration '%s'\n", v.c_str());
        return 2;
      }
    } else if (a == "--no-latency") {
      run.measure_latency = false;
    } else if (a == "--version") {
      std::printf("volcomp-fw-linux %s; gpio backends: fake%s\n", VOLCOMP_VERSION,
                  volcomp::hal::linux_board::HaveLibgpiod() ? ", gpiod (libgpiod 1.6)" : "");
      return 0;
    } else if (a == "--help" || a == "-h") {
      std::printf("%s", kUsage);
      return 0;
    } else {
      std::fprintf(stderr, "volcomp-fw-linux: unknown option '%s'\n%s", a.c_str(), kUsage);
      return 2;
    }
  }
  if (config_path.empty()) {
    std::fprintf(stderr, "volcomp-fw-linux: --config FILE is required\n%s", kUsage);
    return 2;
  }
  const auto loaded = volcomp::linux_board::LoadConfigFile(config_path);
  if (!loaded.ok()) {
    std::fprintf(stderr, "volcomp-fw-linux: %s\n", loaded.error().ToString().c_str());
    return 2;
  }
  const volcomp::linux_board::LinuxBoardConfig& config = *loaded;
  if (check) {
    std::printf("%s", volcomp::linux_board::FormatConfig(config).c_str());
    return 0;
  }
  return volcomp::linux_board::RunLinuxBoard(config, run);
}
