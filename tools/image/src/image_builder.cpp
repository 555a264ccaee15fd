// Hosted image building: quantise, lay out through the lib writer, validate.
#include "volcomp/image/image_builder.hpp"

#include <cmath>
#include <sstream>

#include "element_storage.hpp"
#include "volcomp/table/table_writer.hpp"

namespace volcomp::image {
namespace {

Unexpected<Failure> Invalid(const std::string& message) {
  return Fail(Error::kInputInvalid, "image: " + message);
}

int64_t ElementLimit(table::ElementType type) {
  switch (type) {
    case table::ElementType::kInt16:
      return 32767;
    case table::ElementType::kInt32:
      return 2147483647;
    case table::ElementType::kFloat32:
      return 0;
  }
  return 0;
}

// Calls `fn(value, description)` (an Outcome) for every correction value of the request; stops at
// the first failure.
template <class Fn>
Outcome ForEachValue(const ImageRequest& r, Fn fn) {
  if (r.grid) {
    const auto& g = *r.grid;
    const uint64_t n0 = g.lattice[0].nodes, n1 = g.lattice[1].nodes;
    for (size_t i = 0; i < g.correction_steps.size(); ++i) {
      const uint64_t node = i / 3, c = i % 3;
      VOLCOMP_TRY(fn(g.correction_steps[i], [=] {
        std::ostringstream s;
        s << "GRID3 node (" << node % n0 << ", " << (node / n0) % n1 << ", " << node / (n0 * n1)
          << ") component " << c;
        return s.str();
      }));
    }
  }
  for (const auto& t : r.axis_tables) {
    for (size_t i = 0; i < t.forward_steps.size(); ++i) {
      VOLCOMP_TRY(fn(t.forward_steps[i], [&, i] {
        return "AXIS1D axis " + std::to_string(t.axis) + " forward node " + std::to_string(i);
      }));
    }
    for (size_t i = 0; i < t.reverse_steps.size(); ++i) {
      VOLCOMP_TRY(fn(t.reverse_steps[i], [&, i] {
        return "AXIS1D axis " + std::to_string(t.axis) + " reverse node " + std::to_string(i);
      }));
    }
  }
  return Outcome::Ok();
}

Outcome CheckRequest(const ImageRequest& r) {
  if (r.axes.empty() || r.axes.size() > table::kMaxAxes) {
    return Invalid("1 to 6 axes are needed, got " + std::to_string(r.axes.size()));
  }
  if (!r.grid && r.axis_tables.empty()) return Invalid("no GRID3 and no AXIS1D table");
  if (r.table_id == kNoTableId) {
    return Invalid(
        "table id 0 is reserved (the board reports 0 in 0x2103 when no table is active); "
        "ids start at 1");
  }
  if (r.grid) {
    const auto& g = *r.grid;
    uint64_t nodes = 1;
    for (const auto& l : g.lattice) nodes *= l.nodes;
    if (g.correction_steps.size() != nodes * 3) {
      return Invalid("GRID3 needs " + std::to_string(nodes * 3) + " values, got " +
                     std::to_string(g.correction_steps.size()));
    }
  }
  for (const auto& t : r.axis_tables) {
    if (t.forward_steps.size() != t.lattice.nodes ||
        (!t.reverse_steps.empty() && t.reverse_steps.size() != t.lattice.nodes)) {
      return Invalid("AXIS1D axis " + std::to_string(t.axis) + " needs " +
                     std::to_string(t.lattice.nodes) + " values per direction");
    }
  }
  return ForEachValue(r, [](double v, auto where) -> Outcome {
    if (!std::isfinite(v)) return Invalid(where() + " is not a finite number");
    if (std::fabs(v) > table::kMaxCorrectionSteps) {
      std::ostringstream s;
      s << where() << " = " << v << " steps exceeds the maximum correction of "
        << table::kMaxCorrectionSteps << " steps";
      return Invalid(s.str());
    }
    return Outcome::Ok();
  });
}

ElementStorage Encode(const std::vector<double>& values, table::ElementType type, uint8_t frac) {
  ElementStorage e;
  const double scale = std::ldexp(1.0, frac);
  for (double v : values) {
    switch (type) {
      case table::ElementType::kInt16:
        e.i16.push_back(static_cast<int16_t>(std::llround(v * scale)));
        break;
      case table::ElementType::kInt32:
        e.i32.push_back(static_cast<int32_t>(std::llround(v * scale)));
        break;
      case table::ElementType::kFloat32:
        e.f32.push_back(static_cast<float>(v));
        break;
    }
  }
  return e;
}

Expected<std::string> InfoText(const std::map<std::string, std::string>& info) {
  std::string text;
  for (const auto& [k, v] : info) {
    for (const std::string* s : {&k, &v}) {
      for (char c : *s) {
        if (c == '\n' || c == '\r' || (static_cast<unsigned char>(c) < 0x20 && c != '\t')) {
          return Invalid("INFO entry \"" + k + "\" contains a control character");
        }
      }
    }
    if (k.empty() || k.find('=') != std::string::npos) {
      return Invalid("INFO key \"" + k + "\" must be non-empty and contain no '='");
    }
    text += k + "=" + v + "\n";
  }
  if (text.size() > table::kMaxInfoBytes - 3) return Invalid("INFO text too long");
  return text;
}

}  // namespace

Expected<uint8_t> ChooseFracBits(const ImageRequest& request) {
  VOLCOMP_TRY(CheckRequest(request));
  if (request.element == table::ElementType::kFloat32) return uint8_t{0};
  double max_abs = 0;
  VOLCOMP_TRY(ForEachValue(request, [&](double v, auto) {
    max_abs = std::max(max_abs, std::fabs(v));
    return Outcome::Ok();
  }));
  for (const auto& t : request.axis_tables)
    max_abs = std::max(max_abs, std::fabs(t.backlash_steps));
  const int64_t limit = ElementLimit(request.element);
  for (int f = table::kMaxFracBits; f >= 0; --f) {
    if (std::llround(max_abs * std::ldexp(1.0, f)) <= limit) return static_cast<uint8_t>(f);
  }
  std::ostringstream s;
  s << "a correction of " << max_abs << " steps does not fit int16 even with 0 fraction "
    << "bits; use --element int32";
  return Invalid(s.str());
}

Expected<std::vector<uint8_t>> BuildImage(const ImageRequest& request) {
  VOLCOMP_TRY(CheckRequest(request));
  uint8_t frac = 0;
  if (request.frac_bits) {
    frac = *request.frac_bits;
  } else {
    VOLCOMP_TRY_ASSIGN(frac, ChooseFracBits(request));
  }
  const table::ElementType type = request.element;
  if (type == table::ElementType::kFloat32 && frac != 0) {
    return Invalid("float32 elements take no fraction bits");
  }
  if (frac > table::kMaxFracBits) return Invalid("fraction bits must be 0..8");
  const int64_t limit = ElementLimit(type);
  if (limit != 0) {
    VOLCOMP_TRY(ForEachValue(request, [&](double v, auto where) -> Outcome {
      if (std::llabs(std::llround(v * std::ldexp(1.0, frac))) > limit) {
        std::ostringstream s;
        s << where() << " = " << v << " steps does not fit the element type with " << int(frac)
          << " fraction bits";
        return Invalid(s.str());
      }
      return Outcome::Ok();
    }));
  }

  table::ImageSpec spec;
  spec.table_id = request.table_id;
  spec.axis_count = static_cast<uint8_t>(request.axes.size());
  for (size_t i = 0; i < request.axes.size(); ++i) {
    spec.axes[i] = {request.axes[i].name, request.axes[i].kind, request.axes[i].resolution_e9};
  }
  ElementStorage grid_values;
  table::GridSpec grid;
  if (request.grid) {
    const auto& g = *request.grid;
    grid_values = Encode(g.correction_steps, type, frac);
    grid.frac_bits = frac;
    for (int d = 0; d < 3; ++d) {
      grid.axis[d] = g.axis[d];
      grid.dim[d] = {g.lattice[d].nodes, g.lattice[d].origin_steps, g.lattice[d].spacing_steps};
    }
    grid.values = grid_values.view(type);
    spec.grid = &grid;
  }
  std::vector<ElementStorage> axis_values(request.axis_tables.size() * 2);
  spec.axis1d_count = static_cast<uint8_t>(request.axis_tables.size());
  if (request.axis_tables.size() > table::kMaxAxes) return Invalid("too many AXIS1D");
  for (size_t i = 0; i < request.axis_tables.size(); ++i) {
    const auto& t = request.axis_tables[i];
    table::Axis1dSpec& a = spec.axis1d[i];
    a.axis = t.axis;
    a.frac_bits = frac;
    a.dim = {t.lattice.nodes, t.lattice.origin_steps, t.lattice.spacing_steps};
    a.period_steps = t.wrap_period_steps;
    a.backlash_q8 = static_cast<int32_t>(std::llround(t.backlash_steps * 256.0));
    axis_values[2 * i] = Encode(t.forward_steps, type, frac);
    a.forward = axis_values[2 * i].view(type);
    a.has_reverse = !t.reverse_steps.empty();
    if (a.has_reverse) {
      axis_values[2 * i + 1] = Encode(t.reverse_steps, type, frac);
      a.reverse = axis_values[2 * i + 1].view(type);
    }
  }
  VOLCOMP_TRY_ASSIGN(const std::string info, InfoText(request.info));
  if (!info.empty()) {
    spec.info = info.data();
    spec.info_size = static_cast<uint32_t>(info.size());
  }
  if (request.thermal) {
    if (request.thermal->axis_count != request.axes.size()) {
      return Invalid("the thermal model has " + std::to_string(request.thermal->axis_count) +
                     " axes, the image " + std::to_string(request.axes.size()));
    }
    spec.thermal = &*request.thermal;
  }

  const Result<uint32_t> size = table::ImageSize(spec);
  if (!size.ok()) return Invalid(ErrorText(size.error()));
  std::vector<uint32_t> aligned((*size + 3) / 4);
  uint8_t* out = reinterpret_cast<uint8_t*>(aligned.data());
  const Result<uint32_t> written = table::WriteImage(spec, out, aligned.size() * 4);
  if (!written.ok()) {
    return Invalid(std::string(ErrorText(written.error())) + " (" + ErrorName(written.error()) +
                   ")");
  }
  return std::vector<uint8_t>(out, out + *written);
}

}  // namespace volcomp::image
