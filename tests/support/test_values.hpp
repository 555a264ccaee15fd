// A recording ObjectValues for SDO server tests: holds values per entry in memory and records the
// domain-write calls (begin/data/end) so tests can check what reached the application.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "volcomp/canopen/object_values.hpp"
#include "volcomp/canopen/sdo_abort.hpp"

namespace volcomp::testing {

class TestValues : public canopen::ObjectValues {
 public:
  std::map<canopen::ObjectId, std::vector<uint8_t>> values;
  std::vector<uint8_t> domain;           // bytes received by the current/last domain write
  std::vector<uint8_t> domain_readback;  // what a read of the domain returns
  int begins = 0, ends_ok = 0, ends_failed = 0;
  canopen::SdoAbort last_end = canopen::SdoAbort::kNone;  // outcome of the last domain write
  canopen::AbortOrigin last_end_origin = canopen::AbortOrigin::kServer;  // and who ended it
  uint32_t begin_size = 0;
  canopen::SdoAbort fail_write_with = canopen::SdoAbort::kNone;  // returned by Write if set
  // Returned by DomainWriteData if set (the application refusing data in mid-transfer).
  canopen::SdoAbort fail_domain_data_with = canopen::SdoAbort::kNone;
  // Pacing (ObjectValues::DomainWriteWindow/DomainWriteFlush): the window reported, and how many
  // flush steps each flush takes until it reports done; flush calls counted.
  uint32_t window = 0;
  int flush_steps = 1;
  int flushes = 0;

 private:
  canopen::SdoAbort DoRead(const canopen::ObjectEntry& e,
                           uint32_t offset,
                           uint8_t* buf,
                           uint32_t cap,
                           uint32_t* copied,
                           uint32_t* total) override {
    const std::vector<uint8_t>* v = nullptr;
    std::vector<uint8_t> fixed;
    if (e.type == canopen::DataType::kDomain) {
      v = &domain_readback;
    } else if (values.count(e.id)) {
      v = &values[e.id];
    } else {
      const uint32_t n = canopen::FixedSize(e.type) ? canopen::FixedSize(e.type) : 0;
      for (uint32_t i = 0; i < n; ++i)
        fixed.push_back(static_cast<uint8_t>(e.default_value >> (8 * i)));
      v = &fixed;
    }
    *total = static_cast<uint32_t>(v->size());
    *copied = 0;
    while (offset + *copied < v->size() && *copied < cap) {
      buf[*copied] = (*v)[offset + *copied];
      ++*copied;
    }
    return canopen::SdoAbort::kNone;
  }
  canopen::SdoAbort DoWrite(const canopen::ObjectEntry& e,
                            const uint8_t* data,
                            uint32_t size) override {
    if (canopen::Failed(fail_write_with)) return fail_write_with;
    values[e.id].assign(data, data + size);
    return canopen::SdoAbort::kNone;
  }
  canopen::SdoAbort DoBeginDomainWrite(const canopen::ObjectEntry&, uint32_t size) override {
    ++begins;
    begin_size = size;
    domain.clear();
    return canopen::SdoAbort::kNone;
  }
  canopen::SdoAbort DoDomainWriteData(const uint8_t* data, uint32_t size) override {
    if (canopen::Failed(fail_domain_data_with)) return fail_domain_data_with;
    domain.insert(domain.end(), data, data + size);
    return canopen::SdoAbort::kNone;
  }
  uint32_t DoDomainWriteWindow() override { return window; }
  canopen::SdoAbort DoDomainWriteFlush(bool* done) override {
    ++flushes;
    *done = flushes % flush_steps == 0;
    return canopen::SdoAbort::kNone;
  }
  canopen::SdoAbort DoEndDomainWrite(canopen::SdoAbort outcome,
                                     canopen::AbortOrigin origin) override {
    ++(canopen::Failed(outcome) ? ends_failed : ends_ok);
    last_end = outcome;
    last_end_origin = origin;
    return canopen::SdoAbort::kNone;
  }
};

}  // namespace volcomp::testing
