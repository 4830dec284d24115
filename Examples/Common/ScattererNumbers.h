// Strict parsing of the numbers users type on the example programs' command lines:
// plain decimal only, with a range, and a reason when the text is refused.
#ifndef ScattererNumbers_h
#define ScattererNumbers_h

#include <string>

namespace scatterer_examples
{
/**
 * Parses a plain decimal integer in lo..hi; false with @p why saying what is wrong.
 * Always base 10 ("08" is 8). Hexadecimal, spaces, trailing characters, fractions and
 * exponents are refused: strtol alone (and CLI11's own conversion) would take some.
 */
bool ParseInt(const std::string& text, int lo, int hi, int& value, std::string& why);

/**
 * Parses a plain decimal number in [lo, hi]; false with @p why set. Refuses inf, nan,
 * hexadecimal, values beyond a double and magnitudes below the smallest normal double.
 */
bool ParseDouble(const std::string& text, double lo, double hi, double& value, std::string& why);

/**
 * Parses a window size "WxH", each 16..8192 (plain decimal integers, as every number
 * option); false with @p why saying what is wrong. scatterer-viewer uses it too.
 */
bool ParseSize(const std::string& text, int& width, int& height, std::string& why);

/** A number as messages show it (printf %g). */
std::string FormatNumber(double value);
}

#endif
