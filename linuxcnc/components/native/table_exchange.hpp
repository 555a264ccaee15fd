// Hands tables between the native component's servo-thread function and its loader thread
// (table_loader.hpp) without locks, so that a reload never opens, reads, allocates or frees in
// the servo thread. One exchange per component instance; one thread on each side.
//
//   servo thread:  RequestReload() on the reload pin's rising edge; each period
//                  SwapIn(&active): a published table becomes the active one in one pointer
//                  switch, and the table it replaces goes back to the loader, which frees it.
//   loader thread: TakeRequest(), builds the table, Publish(); Collect() frees retired tables;
//                  Report() posts the outcome for the table-error pin.
//
// A published table is taken only once the loader has collected the previous retired one, so a
// table is freed only after the servo thread has switched away from it.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

#include "native/native_table.hpp"

namespace volcomp::linuxcnc {

class TableExchange {
 public:
  TableExchange() = default;
  TableExchange(const TableExchange&) = delete;
  TableExchange& operator=(const TableExchange&) = delete;
  ~TableExchange() {
    delete pending_.load();
    delete retired_.load();
  }

  // ---- servo thread ----
  void RequestReload() { request_.store(true, std::memory_order_release); }
  /// Makes a published table the active one: `*active` (owned by the exchange's user until now)
  /// goes to the loader to be freed, and the new table is returned through `*active` (true).
  /// False when none is waiting, or the last retired table is not collected yet.
  bool SwapIn(const NativeTable** active) {
    if (retired_.load(std::memory_order_acquire) != nullptr) return false;
    NativeTable* next = pending_.exchange(nullptr, std::memory_order_acq_rel);
    if (next == nullptr) return false;
    retired_.store(const_cast<NativeTable*>(*active), std::memory_order_release);
    *active = next;
    return true;
  }
  /// The outcome of the last reload: 0 or an error code (the table-error pin), and how many
  /// tables were published.
  int32_t last_error() const { return error_.load(std::memory_order_acquire); }
  uint32_t published() const { return published_.load(std::memory_order_acquire); }

  // ---- loader thread ----
  bool TakeRequest() { return request_.exchange(false, std::memory_order_acq_rel); }
  /// Offers `table` to the servo thread; a table published before and not taken yet is dropped.
  void Publish(std::unique_ptr<NativeTable> table) {
    delete pending_.exchange(table.release(), std::memory_order_acq_rel);
    published_.fetch_add(1, std::memory_order_acq_rel);
  }
  /// Frees the table the servo thread switched away from, if any.
  void Collect() { delete retired_.exchange(nullptr, std::memory_order_acq_rel); }
  void Report(int32_t error) { error_.store(error, std::memory_order_release); }
  /// Whether a published table is still waiting (tests).
  bool pending() const { return pending_.load(std::memory_order_acquire) != nullptr; }

 private:
  std::atomic<bool> request_{false};
  std::atomic<NativeTable*> pending_{nullptr};
  std::atomic<NativeTable*> retired_{nullptr};
  std::atomic<int32_t> error_{0};
  std::atomic<uint32_t> published_{0};
};

}  // namespace volcomp::linuxcnc
