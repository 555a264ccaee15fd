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
  uint32_t begin_size = 0;
  uint32_t fail_write_with = 0;  // abort code to return from Write, if non-zero

 private:
  uint32_t DoRead(const canopen::ObjectEntry& e,
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
    return 0;
  }
  uint32_t DoWrite(const canopen::ObjectEntry& e, const uint8_t* data, uint32_t size) override {
    if (fail_write_with != 0) return fail_write_with;
    values[e.id].assign(data, data + size);
    return 0;
  }
  uint32_t DoBeginDomainWrite(const canopen::ObjectEntry&, uint32_t size) override {
    ++begins;
    begin_size = size;
    domain.clear();
    return 0;
  }
  uint32_t DoDomainWriteData(const uint8_t* data, uint32_t size) override {
    domain.insert(domain.end(), data, data + size);
    return 0;
  }
  uint32_t DoEndDomainWrite(bool complete) override {
    ++(complete ? ends_ok : ends_failed);
    return 0;
  }
};

}  // namespace volcomp::testing
