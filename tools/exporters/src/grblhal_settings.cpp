// grblHAL $160… backlash settings (see grblhal_settings.hpp).
#include "volcomp/exporters/grblhal_settings.hpp"

#include <string>

namespace volcomp::exporters {

Expected<GrblhalSettings> BuildGrblhalSettings(const std::vector<AxisBacklash>& backlash) {
  if (backlash.empty()) return Fail(Error::kInvalidArgument, "grblHAL: no axis test given");
  GrblhalSettings g;
  std::string lines;
  for (const AxisBacklash& b : backlash) {
    VOLCOMP_TRY(RequireBacklashAxis(b, kGrblhalAxes, true, "grblHAL"));
    VOLCOMP_TRY(RequireLostMotion(b, "grblHAL"));
    GrblhalSetting s;
    s.axis = b.axis;
    s.number = kGrblhalBacklashSetting + static_cast<int>(std::string(kGrblhalAxes).find(b.axis));
    s.value = BacklashInFileUnits(b);
    g.settings.push_back(s);
    lines += "$" + std::to_string(s.number) + "=" + FixedDecimals(s.value, 5) + "\n";
  }
  std::string& t = g.text;
  t = "; grblHAL backlash compensation\n";
  t += HobbyInputLines("; ", "export grblhal", {}, backlash);
  t +=
      "; Backlash: the lost motion b = -(ISO 230-2 mean reversal), the distance grblHAL adds when\n"
      ";   the axis reverses (motion_control.c, rounded to whole steps), mm (deg on a rotary\n"
      ";   axis). $160 + axis index (X 0, Y 1, Z 2, A 3, B 4, C 5, U 6, V 7; settings.h); needs a\n"
      ";   build with ENABLE_BACKLASH_COMPENSATION.\n";
  t += lines;
  return g;
}

}  // namespace volcomp::exporters
