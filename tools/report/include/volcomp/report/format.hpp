// Number formatting and escaping shared by the text, HTML and SVG writers.
#pragma once

#include <string>

namespace volcomp::report {

/// `value` with exactly `decimals` digits after the point ("-0.00" is printed as "0.00").
/// NaN and infinities are printed as "n/a".
std::string FormatFixed(double value, int decimals);

/// `value` with a sign always shown ("+1.25", "-0.40"), otherwise as FormatFixed.
std::string FormatSigned(double value, int decimals);

/// `value` with up to `significant` significant digits, no trailing zeros ("0.1", "-12.5").
std::string FormatNumber(double value, int significant = 10);

/// Escapes &, <, >, " and ' for use in HTML/SVG text and attribute values.
std::string EscapeXml(const std::string& text);

}  // namespace volcomp::report
