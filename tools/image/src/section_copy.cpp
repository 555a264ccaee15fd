// Copying sections of an image into a new one.
#include "section_copy.hpp"

#include <cstring>

namespace volcomp::image {
namespace {

// An element array of the image decoded into typed storage (little-endian in the image), so the
// writer re-encodes exactly the same values.
ElementStorage Decode(const uint8_t* p, table::ElementType type, uint64_t count) {
  ElementStorage e;
  for (uint64_t i = 0; i < count; ++i) {
    if (type == table::ElementType::kInt16) {
      const uint16_t u = static_cast<uint16_t>(p[2 * i] | (p[2 * i + 1] << 8));
      e.i16.push_back(static_cast<int16_t>(u));
    } else {
      const uint32_t u =
          static_cast<uint32_t>(p[4 * i]) | (static_cast<uint32_t>(p[4 * i + 1]) << 8) |
          (static_cast<uint32_t>(p[4 * i + 2]) << 16) | (static_cast<uint32_t>(p[4 * i + 3]) << 24);
      if (type == table::ElementType::kInt32) {
        e.i32.push_back(static_cast<int32_t>(u));
      } else {
        float f;
        std::memcpy(&f, &u, sizeof f);
        e.f32.push_back(f);
      }
    }
  }
  return e;
}

}  // namespace

void CopyGrid(const table::TableView& v, SectionCopy* copy, table::ImageSpec* spec) {
  const table::Grid3View& g = v.grid;
  const uint64_t count = uint64_t{g.dim[0].nodes} * g.dim[1].nodes * g.dim[2].nodes * 3;
  copy->values.push_back(Decode(g.data, g.type, count));
  copy->grid.frac_bits = g.frac_bits;
  for (int d = 0; d < 3; ++d) {
    copy->grid.axis[d] = g.axis[d];
    copy->grid.dim[d] = g.dim[d];
  }
  copy->grid.values = copy->values.back().view(g.type);
  spec->grid = &copy->grid;
}

void CopyAxis1d(const table::Axis1dView& t,
                uint8_t axis,
                SectionCopy* copy,
                table::ImageSpec* spec) {
  table::Axis1dSpec& s = spec->axis1d[spec->axis1d_count++];
  s.axis = axis;
  s.frac_bits = t.frac_bits;
  s.dim = t.dim;
  s.period_steps = t.period_steps;
  s.backlash_q8 = t.backlash_q8;
  copy->values.push_back(Decode(t.forward, t.type, t.dim.nodes));
  s.forward = copy->values.back().view(t.type);
  s.has_reverse = t.reverse != nullptr;
  if (s.has_reverse) {
    copy->values.push_back(Decode(t.reverse, t.type, t.dim.nodes));
    s.reverse = copy->values.back().view(t.type);
  }
}

std::string PrefixedInfo(const table::TableView& v, const std::string& prefix) {
  std::string out;
  if (v.info == nullptr) return out;
  const std::string text(v.info, v.info_size);
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    if (!line.empty() && line.find_first_not_of('\0') != std::string::npos) {
      out += prefix + line.substr(0, line.find('\0')) + "\n";
    }
    start = end + 1;
  }
  return out;
}

Outcome SetInfo(std::string info,
                const std::string& extra,
                const std::string& what,
                std::string* text,
                std::vector<std::string>* warnings,
                table::ImageSpec* spec) {
  for (char c : info) {
    if (c != '\n' && c != '\t' && static_cast<unsigned char>(c) < 0x20) {
      return Fail(Error::kInputInvalid, "INFO text contains a control character");
    }
  }
  if (info.size() > table::kMaxInfoBytes - 3)
    return Fail(Error::kInputInvalid, "INFO text too long");
  if (info.size() + extra.size() <= table::kMaxInfoBytes - 3) {
    info += extra;
  } else {
    warnings->push_back("the INFO lines of " + what +
                        " do not fit the new image's INFO section: left out");
  }
  *text = std::move(info);
  spec->info = text->data();
  spec->info_size = static_cast<uint32_t>(text->size());
  return Outcome::Ok();
}

Expected<std::vector<uint8_t>> WriteSpec(const table::ImageSpec& spec) {
  const Result<uint32_t> size = table::ImageSize(spec);
  if (!size.ok())
    return Fail(Error::kInputInvalid, std::string("image: ") + ErrorText(size.error()));
  std::vector<uint32_t> aligned((*size + 3) / 4);
  uint8_t* bytes = reinterpret_cast<uint8_t*>(aligned.data());
  const Result<uint32_t> written = table::WriteImage(spec, bytes, aligned.size() * 4);
  if (!written.ok()) {
    return Fail(Error::kInputInvalid, std::string("image: ") + ErrorText(written.error()) + " (" +
                                          ErrorName(written.error()) + ")");
  }
  return std::vector<uint8_t>(bytes, bytes + *written);
}

}  // namespace volcomp::image
