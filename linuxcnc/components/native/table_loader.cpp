// The native component's loader thread (see the header).
#include "native/table_loader.hpp"

#include <pthread.h>

#include <chrono>
#include <cstdio>
#include <utility>

namespace volcomp::linuxcnc {

void TableLoader::Start(std::vector<Job> jobs) {
  jobs_ = std::move(jobs);
  stop_.store(false);
  thread_ = std::thread([this] { Run(); });
  // Named in `ps -L` and /proc/PID/task/*/comm: it is not one of HAL's realtime threads.
  pthread_setname_np(thread_.native_handle(), "volcomp-loader");
}

void TableLoader::Stop() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

void TableLoader::Run() {
  while (!stop_.load()) {
    Poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(poll_ms_));
  }
  Poll();  // frees a table retired in the last period
}

void TableLoader::Poll() {
  for (Job& job : jobs_) {
    job.exchange->Collect();
    if (!job.exchange->TakeRequest()) continue;
    Expected<std::unique_ptr<NativeTable>> t = NativeTable::ReadFile(job.path);
    Outcome same = t.ok() ? job.first->CheckSameAxes(**t, job.path) : Outcome::Ok();
    if (!t.ok() || !same.ok()) {
      const Failure& f = !t.ok() ? t.error() : same.error();
      job.exchange->Report(static_cast<int32_t>(f.code));
      print_(Level::kError, job.name + ": " + f.message + "; the active table stays");
      continue;
    }
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08X", (*t)->crc32());
    print_(Level::kInfo, job.name + ": table \"" + job.path + "\" read again (" +
                             std::to_string((*t)->size_bytes()) + " bytes, CRC-32 " + crc +
                             "); it becomes active in the next servo period");
    job.exchange->Report(0);
    job.exchange->Publish(std::move(*t));
  }
}

}  // namespace volcomp::linuxcnc
