// volcomp-fw-linux's event loop.
#include "volcomp/linux_board/linux_runner.hpp"

#include <linux/sockios.h>
#include <sched.h>
#include <sys/epoll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>

#include "volcomp/firmware/gateway_app.hpp"
#include "volcomp/hal/linux/monotonic_clock.hpp"
#include "volcomp/hal/linux/shutdown_signal.hpp"
#include "volcomp/hal/linux/socketcan_port.hpp"
#include "volcomp/linux_board/latency_stats.hpp"
#include "volcomp/linux_board/linux_board.hpp"

namespace volcomp::linux_board {
namespace {

using firmware::GatewayApp;
using firmware::GatewayAppCounters;
namespace lb = hal::linux_board;
using hal::socketcan::SocketCanPort;

constexpr int kFrameBudget = 64;  // frames per port per loop pass (keeps the tick on time)

uint64_t RealtimeNs() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<uint64_t>(ts.tv_sec) * 1000000000u + static_cast<uint64_t>(ts.tv_nsec);
}

// Kernel receive time of the last frame read from `fd` (CLOCK_REALTIME), or 0.
uint64_t KernelStampNs(int fd) {
  timespec ts{};
  if (ioctl(fd, SIOCGSTAMPNS, &ts) != 0) return 0;
  return static_cast<uint64_t>(ts.tv_sec) * 1000000000u + static_cast<uint64_t>(ts.tv_nsec);
}

struct Direction {
  LatencyStats kernel_to_write;  // kernel receive timestamp -> write() of the forward returned
  LatencyStats in_process;       // read() returned -> write() returned
  uint64_t unstamped = 0;        // forwarded frames without a usable kernel timestamp
  bool skip_stamps = false;      // the port was serviced in batch since the last drain
};

class Runner {
 public:
  Runner(const LinuxBoardConfig& config, const RunOptions& options)
      : config_(config), options_(options), board_(config, BoardOptions()) {}

  int Run();

 private:
  LinuxBoard::Options BoardOptions() {
    LinuxBoard::Options o;
    o.bus_detail = [this] { return DescribeBitrate(controller_, config_.controller_iface); };
    return o;
  }
  bool Open();
  void LogStart();
  std::string DescribeBitrate(const SocketCanPort& port, const std::string& iface) const;
  void DrainController();
  void DrainDrives();
  void OnTimer();
  void Shutdown();
  void Report();
  SocketCanPort::Options PortOptions() const {
    SocketCanPort::Options o;
    o.tx_capacity = config_.tx_queue;
    o.restart_on_bus_off = config_.restart_on_bus_off;
    return o;
  }

  const LinuxBoardConfig& config_;
  RunOptions options_;
  lb::ShutdownSignal signal_;
  lb::MonotonicClock clock_;
  SocketCanPort controller_;
  SocketCanPort drives_;
  bool have_drives_ = false;
  LinuxBoard board_;
  GatewayApp* app_ = nullptr;
  Direction to_drives_, to_controller_;
  uint64_t stop_at_ns_ = 0, started_ns_ = 0;
  int stop_signal_ = 0;
  bool stop_ = false;
};

bool Runner::Open() {
  auto fail = [](const std::string& what) {
    std::fprintf(stderr, "volcomp-fw-linux: %s\n", what.c_str());
    return false;
  };
  Expected<void> opened = signal_.Open();
  if (!opened.ok()) return fail(opened.error().message);
  opened = controller_.Open(config_.controller_iface, PortOptions());
  if (!opened.ok()) return fail("controller side: " + opened.error().message);
  have_drives_ = !config_.drives_iface.empty();
  if (have_drives_) {
    opened = drives_.Open(config_.drives_iface, PortOptions());
    if (!opened.ok()) return fail("drive side: " + opened.error().message);
  }
  opened = board_.Open(&controller_, have_drives_ ? &drives_ : nullptr);
  if (!opened.ok()) return fail(opened.error().message);
  app_ = &board_.app();
  // Real-time scheduling last, once everything is allocated.
  if (config_.lock_memory && mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
    std::fprintf(stderr, "volcomp-fw-linux: warning: mlockall: %s (needs CAP_IPC_LOCK)\n",
                 std::strerror(errno));
  }
  if (config_.realtime_priority != 0) {
    sched_param sp{};
    sp.sched_priority = static_cast<int>(config_.realtime_priority);
    if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0) {
      std::fprintf(stderr,
                   "volcomp-fw-linux: warning: SCHED_FIFO priority %u: %s (needs CAP_SYS_NICE; "
                   "running with normal scheduling)\n",
                   config_.realtime_priority, std::strerror(errno));
    }
  }
  LogStart();
  return true;
}

// What the controller port found when the board applied its bit rate.
std::string Runner::DescribeBitrate(const SocketCanPort& port, const std::string& iface) const {
  const SocketCanPort::BitrateCheck& b = port.bitrate_check();
  if (!b.interface_bps) return iface + " reports no bit rate to compare: " + b.note;
  if (*b.interface_bps == b.configured_bps) {
    return iface + " runs at " + std::to_string(*b.interface_bps / 1000u) + " kbit/s";
  }
  return port.last_failure() ? port.last_failure()->message : iface + ": bit rate mismatch";
}

void Runner::LogStart() {
  const GatewayApp::App& app = app_->app();
  const Status stored = app.stored_table_status();
  std::fprintf(stderr,
               "volcomp-fw-linux: node 0x%02X on %s, %s%s, %u axes, tick %u Hz, gpio %s, stored "
               "table: %s\n",
               app.settings().node_id, config_.controller_iface.c_str(),
               have_drives_ ? "gateway to " : "no gateway",
               have_drives_ ? config_.drives_iface.c_str() : "",
               unsigned{app.control_tick().axis_count()}, app.settings().board.tick_hz,
               config_.gpio_backend == GpioBackendKind::kNone ? "none (inputs inactive)"
                                                              : board_.gpio().Describe().c_str(),
               stored.ok() ? "active" : ErrorText(stored.error()));
  std::fprintf(stderr, "volcomp-fw-linux: configuration in force: %s\n",
               board_.DescribeConfigInForce().c_str());
}

void Runner::DrainController() {
  Direction& d = to_drives_;
  const bool stamp = options_.measure_latency && !d.skip_stamps && have_drives_;
  d.skip_stamps = false;
  for (int i = 0; i < kFrameBudget; ++i) {
    CanFrame f;
    if (!controller_.Receive(&f)) break;
    const uint64_t t_read = clock_.NowNs();
    const uint64_t k_rx = stamp ? KernelStampNs(controller_.fd()) : 0;
    const gateway::Route route = app_->OnControllerFrame(f);
    if (route != gateway::Route::kForward || !have_drives_ || !options_.measure_latency) continue;
    const uint64_t t_done = clock_.NowNs();
    const uint64_t r_done = RealtimeNs();
    d.in_process.Add(t_done - t_read);
    if (k_rx != 0 && r_done >= k_rx && drives_.pending_tx() == 0) {
      d.kernel_to_write.Add(r_done - k_rx);
    } else {
      ++d.unstamped;
    }
  }
  if (app_->node_pending()) app_->Poll();  // answer SDO requests at once
}

void Runner::DrainDrives() {
  Direction& d = to_controller_;
  const bool stamp = options_.measure_latency && !d.skip_stamps;
  d.skip_stamps = false;
  for (int i = 0; i < kFrameBudget; ++i) {
    CanFrame f;
    if (!drives_.Receive(&f)) break;
    const uint64_t t_read = clock_.NowNs();
    const uint64_t k_rx = stamp ? KernelStampNs(drives_.fd()) : 0;
    const gateway::Route route = app_->OnDriveFrame(f);
    if (route != gateway::Route::kForward || !options_.measure_latency) continue;
    const uint64_t t_done = clock_.NowNs();
    const uint64_t r_done = RealtimeNs();
    d.in_process.Add(t_done - t_read);
    if (k_rx != 0 && r_done >= k_rx && controller_.pending_tx() == 0) {
      d.kernel_to_write.Add(r_done - k_rx);
    } else {
      ++d.unstamped;
    }
  }
}

void Runner::OnTimer() {
  board_.OnTimer();
  const uint64_t now = clock_.NowNs();
  // Frames deferred by ENOBUFS pacing: flush them (Service() also reads waiting frames into the
  // port's queue, whose kernel timestamps are then unknown).
  if (controller_.pending_tx() != 0) {
    controller_.Service();
    to_drives_.skip_stamps = true;
  }
  if (have_drives_ && drives_.pending_tx() != 0) {
    drives_.Service();
    to_controller_.skip_stamps = true;
  }
  if (stop_at_ns_ != 0 && now >= stop_at_ns_) stop_ = true;
}

void Runner::Shutdown() {
  board_.Shutdown();
  for (int i = 0;
       i < 100 && (controller_.pending_tx() != 0 || (have_drives_ && drives_.pending_tx() != 0));
       ++i) {
    controller_.Service();
    if (have_drives_) drives_.Service();
    usleep(1000);
  }
}

void Runner::Report() {
  const gateway::GatewayCounters& g = app_->gateway().counters();
  const GatewayAppCounters& a = app_->counters();
  const TickCounters& t = board_.tick_counters();
  const double run_s = static_cast<double>(clock_.NowNs() - started_ns_) * 1e-9;
  std::fprintf(stderr,
               "volcomp-fw-linux: stopped%s after %.1f s: %llu ticks (%llu late, %llu skipped), "
               "longest tick %llu ns\n",
               stop_signal_ != 0 ? " by signal" : "", run_s,
               static_cast<unsigned long long>(t.ticks), static_cast<unsigned long long>(t.late),
               static_cast<unsigned long long>(t.skipped),
               static_cast<unsigned long long>(t.max_tick_ns));
  std::fprintf(stderr,
               "  frames: %u from controller (%u to drives, %u for the node, %u SYNC), %u from "
               "drives (%u to controller, %u conflicts); targets corrected %u, actuals corrected "
               "%u, short PDOs %u, send failures %u; lost by the kernel (receive buffer full): "
               "%llu from controller, %llu from drives\n",
               g.from_controller, a.forwarded_to_drives, g.local, g.syncs, g.from_drives,
               a.forwarded_to_controller, g.conflicts, g.targets_corrected, g.actuals_corrected,
               g.short_pdos, a.send_failures,
               static_cast<unsigned long long>(controller_.counters().rx_dropped),
               static_cast<unsigned long long>(have_drives_ ? drives_.counters().rx_dropped : 0));
  const lb::FileFlash::Counters fc = board_.tables().counters();
  const std::optional<Failure> flash_error = board_.tables().write_error();
  std::fprintf(stderr, "  table flash: %llu erases, %llu programs, most queued %llu%s%s\n",
               static_cast<unsigned long long>(fc.erases),
               static_cast<unsigned long long>(fc.programs),
               static_cast<unsigned long long>(fc.max_queued), flash_error ? "; error: " : "",
               flash_error ? flash_error->message.c_str() : "");
  if (have_drives_ && options_.measure_latency) {
    std::fprintf(stderr, "  latency controller->drives, kernel rx -> forwarded write: %s\n",
                 to_drives_.kernel_to_write.Summary().c_str());
    std::fprintf(stderr, "  latency controller->drives, in process: %s\n",
                 to_drives_.in_process.Summary().c_str());
    std::fprintf(stderr, "  latency drives->controller, kernel rx -> forwarded write: %s\n",
                 to_controller_.kernel_to_write.Summary().c_str());
    std::fprintf(stderr, "  latency drives->controller, in process: %s\n",
                 to_controller_.in_process.Summary().c_str());
  }
  if (options_.stats_file.empty()) return;
  std::ofstream f(options_.stats_file, std::ios::trunc);
  auto dir = [](const Direction& d) {
    return "{\"kernel_to_write\":" + d.kernel_to_write.Json() +
           ",\"in_process\":" + d.in_process.Json() +
           ",\"unstamped\":" + std::to_string(d.unstamped) + "}";
  };
  f << "{\"run_s\":" << run_s << ",\"ticks\":" << t.ticks << ",\"late_ticks\":" << t.late
    << ",\"skipped_ticks\":" << t.skipped << ",\"max_tick_ns\":" << t.max_tick_ns
    << ",\"from_controller\":" << g.from_controller << ",\"from_drives\":" << g.from_drives
    << ",\"forwarded_to_drives\":" << a.forwarded_to_drives
    << ",\"forwarded_to_controller\":" << a.forwarded_to_controller << ",\"local\":" << g.local
    << ",\"syncs\":" << g.syncs << ",\"targets_corrected\":" << g.targets_corrected
    << ",\"actuals_corrected\":" << g.actuals_corrected << ",\"short_pdos\":" << g.short_pdos
    << ",\"conflicts\":" << g.conflicts << ",\"send_failures\":" << a.send_failures
    << ",\"rx_dropped_controller\":" << controller_.counters().rx_dropped
    << ",\"rx_dropped_drives\":" << (have_drives_ ? drives_.counters().rx_dropped : 0)
    << ",\"controller_to_drives\":" << dir(to_drives_)
    << ",\"drives_to_controller\":" << dir(to_controller_) << "}\n";
}

int Runner::Run() {
  if (!Open()) return 1;
  started_ns_ = clock_.NowNs();
  if (options_.duration_s > 0) {
    stop_at_ns_ = started_ns_ + static_cast<uint64_t>(options_.duration_s * 1e9);
  }
  const int ep = epoll_create1(EPOLL_CLOEXEC);
  if (ep < 0) {
    std::fprintf(stderr, "volcomp-fw-linux: epoll_create1: %s\n", std::strerror(errno));
    return 1;
  }
  enum : uint64_t { kController = 1, kDrives, kTimer, kSignal };
  auto watch = [&](int fd, uint64_t tag) {
    epoll_event ev{};
    ev.events = EPOLLIN;
    ev.data.u64 = tag;
    return epoll_ctl(ep, EPOLL_CTL_ADD, fd, &ev) == 0;
  };
  if (!watch(controller_.fd(), kController) || (have_drives_ && !watch(drives_.fd(), kDrives)) ||
      !watch(board_.tick_timer().fd(), kTimer) || !watch(signal_.fd(), kSignal)) {
    std::fprintf(stderr, "volcomp-fw-linux: epoll_ctl: %s\n", std::strerror(errno));
    close(ep);
    return 1;
  }
  if (!options_.ready_file.empty()) {
    std::ofstream(options_.ready_file, std::ios::trunc) << getpid() << "\n";
  }
  while (!stop_) {
    epoll_event events[8];
    const int n = epoll_wait(ep, events, 8, -1);
    if (n < 0) {
      if (errno == EINTR) continue;
      std::fprintf(stderr, "volcomp-fw-linux: epoll_wait: %s\n", std::strerror(errno));
      break;
    }
    for (int i = 0; i < n; ++i) {
      switch (events[i].data.u64) {
        case kController:
          DrainController();
          break;
        case kDrives:
          DrainDrives();
          break;
        case kTimer:
          OnTimer();
          break;
        case kSignal:
          stop_signal_ = signal_.Take();
          stop_ = true;
          break;
        default:
          break;
      }
    }
  }
  close(ep);
  Shutdown();
  Report();
  return 0;
}

}  // namespace

int RunLinuxBoard(const LinuxBoardConfig& config, const RunOptions& options) {
  Runner runner(config, options);
  return runner.Run();
}

}  // namespace volcomp::linux_board
