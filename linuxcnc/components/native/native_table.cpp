// Reading, validating and preparing a table for the native component (see the header).
#include "native/native_table.hpp"

#include <cstdio>
#include <utility>

#include "table_file.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::linuxcnc {
Expected<std::unique_ptr<NativeTable>> NativeTable::ReadFile(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(std::vector<uint8_t> bytes, ReadTableFile(path));
  return FromBytes(std::move(bytes), path);
}

Expected<std::unique_ptr<NativeTable>> NativeTable::FromBytes(std::vector<uint8_t> bytes,
                                                              const std::string& source) {
  std::unique_ptr<NativeTable> t(new NativeTable());
  t->bytes_ = std::move(bytes);  // the view below points into this buffer, which no longer moves
  const Result<table::TableView> view = table::ParseImage(t->bytes_.data(), t->bytes_.size());
  if (!view.ok()) {
    return Fail(view.status().error(), ImageRefusal(source, view.status()));
  }
  // The component has no temperature channels: a thermal model is refused, never dropped.
  if (view->thermal != nullptr) {
    return Fail(Error::kThermalNotApplied,
                "table \"" + source + "\" refused: " + ErrorText(Error::kThermalNotApplied) + " (" +
                    ErrorName(Error::kThermalNotApplied) + ")");
  }
  // PreparedTable::Prepare checks the image against a board's axes: here the image's own.
  BoardConfig c;
  c.axis_count = view->axis_count;
  for (uint8_t a = 0; a < view->axis_count; ++a) {
    c.axis[a].name = view->axes[a].name;
    c.axis[a].kind = view->axes[a].kind;
    c.axis[a].resolution_e9 = view->axes[a].resolution_e9;
  }
  const Status prepared = t->prepared_.Prepare(*view, c);
  if (!prepared.ok()) {
    return Fail(prepared.error(), "table \"" + source + "\"" + " refused: " +
                                      ErrorText(prepared.error()) + " (" + prepared.name() + ")");
  }
  t->axis_count_ = view->axis_count;
  for (uint8_t a = 0; a < view->axis_count; ++a) {
    NativeAxis& x = t->axes_[a];
    x.name = view->axes[a].name;
    x.kind = view->axes[a].kind;
    x.resolution_e9 = view->axes[a].resolution_e9;
    x.units_per_step = view->axes[a].resolution_e9 * 1e-9;
  }
  for (uint8_t i = 0; i < view->axis1d_count; ++i) {
    const table::Axis1dView& v = view->axis1d[i];
    if (v.period_steps != 0) {
      t->axes_[v.axis].wrap_period_steps = v.period_steps;
      t->axes_[v.axis].wrap_origin_steps = v.dim.origin_steps;
    }
  }
  return t;
}

int NativeTable::FindAxis(char letter) const {
  for (uint8_t a = 0; a < axis_count_; ++a) {
    if (axes_[a].name == letter) return a;
  }
  return -1;
}

std::string NativeTable::AxisNames() const {
  std::string s;
  for (uint8_t a = 0; a < axis_count_; ++a) {
    if (a > 0) s += ' ';
    s += axes_[a].name;
  }
  return s;
}

Outcome NativeTable::CheckSameAxes(const NativeTable& other, const std::string& source) const {
  bool same = other.axis_count_ == axis_count_;
  for (uint8_t a = 0; same && a < axis_count_; ++a) {
    same = other.axes_[a].name == axes_[a].name && other.axes_[a].kind == axes_[a].kind &&
           other.axes_[a].resolution_e9 == axes_[a].resolution_e9;
  }
  if (same) return Outcome::Ok();
  auto describe = [](const NativeTable& t) {
    std::string s;
    for (uint8_t a = 0; a < t.axis_count_; ++a) {
      char b[64];
      std::snprintf(b, sizeof b, "%s%c %s %.9g %s/step", a > 0 ? ", " : "", t.axes_[a].name,
                    t.axes_[a].kind == table::AxisKind::kRotary ? "rotary" : "linear",
                    t.axes_[a].units_per_step,
                    t.axes_[a].kind == table::AxisKind::kRotary ? "deg" : "mm");
      s += b;
    }
    return s;
  };
  return Fail(Error::kConfigAxisMismatch,
              "table \"" + source + "\"" + " refused: its axes (" + describe(other) +
                  ") differ from those the component was loaded with (" + describe(*this) +
                  "); a reload must be a table for the same machine (" +
                  ErrorName(Error::kConfigAxisMismatch) + ")");
}

}  // namespace volcomp::linuxcnc
