// The native component's loader thread: an ordinary (non-realtime) thread of rtapi_app that reads
// and checks the table files on a reload request and publishes the prepared tables through each
// instance's TableExchange; it also frees the tables the servo thread switched away from. The
// servo thread only posts requests and switches pointers (table_exchange.hpp).
//
// Requests are polled every `poll_ms` (10 ms): a reload takes effect one to two polls plus the
// file's reading and validation after the reload pin's rising edge. Messages (refusals with their
// reason, accepted tables) go to `print`, which must be callable from this thread.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "native/native_table.hpp"
#include "native/table_exchange.hpp"

namespace volcomp::linuxcnc {

class TableLoader {
 public:
  enum class Level { kInfo, kError };
  using PrintFn = void (*)(Level level, const std::string& message);

  struct Job {
    std::string name;          // instance name, prefixes the messages
    std::string path;          // the table file, read again on each request
    const NativeTable* first;  // the table loaded at start: a reload must match its axes
    TableExchange* exchange;
  };

  explicit TableLoader(PrintFn print, int poll_ms = 10) : print_(print), poll_ms_(poll_ms) {}
  ~TableLoader() { Stop(); }
  TableLoader(const TableLoader&) = delete;
  TableLoader& operator=(const TableLoader&) = delete;

  /// Starts the thread for `jobs` (the first tables and exchanges must outlive Stop()).
  void Start(std::vector<Job> jobs);
  /// Stops and joins the thread (idempotent).
  void Stop();
  /// One pass over the jobs, as the thread makes every poll (tests call it directly).
  void Poll();

 private:
  void Run();
  PrintFn print_;
  int poll_ms_;
  std::vector<Job> jobs_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace volcomp::linuxcnc
