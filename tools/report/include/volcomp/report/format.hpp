// Number formatting and escaping shared by the text, HTML and SVG writers.
#pragma once

#include <cstddef>
#include <string>

namespace volcomp::report {

/// `value` with exactly `decimals` digits after the point ("-0.00" is printed as "0.00").
/// NaN and infinities are printed as "n/a".
std::string FormatFixed(double value, int decimals);

/// `value` with a sign always shown ("+1.25", "-0.40"), otherwise as FormatFixed.
std::string FormatSigned(double value, int decimals);

/// `value` with up to `significant` significant digits, no trailing zeros ("0.1", "-12.5").
std::string FormatNumber(double value, int significant = 10);

/// Width of UTF-8 `text` in a monospaced terminal: characters, not counting combining marks
/// (U+0300..U+036F), for aligning columns that hold symbols such as "A↑" or "B̄".
std::size_t DisplayWidth(const std::string& text);

/// `text` padded with spaces to `width` display columns (unchanged when already wider).
std::string PadRight(const std::string& text, std::size_t width);

/// Escapes &, <, >, " and ' for use in HTML/SVG text and attribute values.
std::string EscapeXml(const std::string& text);

}  // namespace volcomp::report
