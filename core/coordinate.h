// What a coordinate is, in every reader (docs/CONTRACT.md, "Coordinates").
//
// Grammar: a decimal number [+-]?(D+(.D*)?|.D+)([eE][+-]?D+)? (GeoJSON: JSON's own, stricter grammar,
// which its parser checks first), or nan / inf / infinity with an optional sign, which read as
// non-finite values so that the polygon check names the vertex. Value: an integer (no point, no
// exponent) must be exactly a double; any other form is its nearest double (round to nearest even,
// as strtod); a non-zero value whose magnitude is below the smallest normal double (2.2e-308) is
// refused as too small, as one above the largest (1.8e308) is refused as too large. So a number is
// never silently changed: what is read is the number written, or its nearest double when it has a
// fraction or an exponent, or an error.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace pd {

// The coordinate `text` names, or nullopt with `why` set to the reason (e.g. "'1e-400' is too small
// for a double (it is not 0)"); the reason quotes the text with quoted_input.
std::optional<double> coordinate_value(std::string_view text, std::string& why);

// An ASCII digit, as both number grammars (the coordinate rule, JSON's) spell it; not the locale's.
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The fast path of the rule for the plain numbers that fill large files: [-]D+ of at most 15 characters
// or [-]D*.D* of at most 300 characters, read in one pass (from_chars for a decimal) at `at`, which it
// moves past the number. Such a number can neither overflow, underflow nor be an integer that no
// double holds, so its value is what coordinate_value gives. Returns nothing (and leaves `at`) for any
// other text, which coordinate_value reads; the caller checks what follows the number.
std::optional<double> plain_coordinate(const char*& at, const char* end);

// Input text quoted for an error message: at most `limit` characters, control bytes, NUL and bytes
// above 126 as \xNN escapes, between single quotes.
std::string quoted_input(std::string_view text, std::size_t limit = 40);

}  // namespace pd
