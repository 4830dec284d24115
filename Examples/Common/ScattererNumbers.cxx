#include "ScattererNumbers.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace scatterer_examples
{
std::string FormatNumber(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}

namespace
{
/**
 * Why @p text is not a plain decimal number (an integer when @p integer), or "" if
 * it is one. strtod and strtol alone would take " 5" (leading space), "0x10"
 * (hexadecimal; strtod even reads hexadecimal fractions), "inf" and "nan", and a
 * user who typed them most likely meant something else.
 */
std::string DecimalSyntaxProblem(const std::string& text, bool integer)
{
  if (text.empty())
  {
    return "empty; a number is needed";
  }
  if (std::isspace(static_cast<unsigned char>(text.front())) ||
    std::isspace(static_cast<unsigned char>(text.back())))
  {
    return "has spaces around it; write the number alone";
  }
  size_t i = text[0] == '+' || text[0] == '-' ? 1 : 0;
  std::string rest = text.substr(i);
  std::transform(rest.begin(), rest.end(), rest.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (rest.rfind("inf", 0) == 0 || rest.rfind("nan", 0) == 0)
  {
    return "not a finite number (inf and nan are refused)";
  }
  if (rest.rfind("0x", 0) == 0)
  {
    return "hexadecimal is not accepted; write the number in decimal";
  }
  // [+-] digits [. digits] [e [+-] digits], or [+-] . digits [e ...].
  const auto digits = [&]()
  {
    const size_t from = i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])))
    {
      ++i;
    }
    return i - from;
  };
  size_t mantissa = digits();
  bool fraction = false;
  if (i < text.size() && text[i] == '.')
  {
    ++i;
    fraction = true;
    mantissa += digits();
  }
  bool exponent = false;
  if (mantissa > 0 && i < text.size() && (text[i] == 'e' || text[i] == 'E'))
  {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-'))
    {
      ++i;
    }
    exponent = true;
    if (digits() == 0)
    {
      mantissa = 0; // "1e" or "1e+": no exponent digits
    }
  }
  if (mantissa == 0 || i != text.size())
  {
    return integer ? "not a decimal integer" : "not a decimal number";
  }
  if (integer && (fraction || exponent))
  {
    return "not an integer";
  }
  return std::string();
}
}

bool ParseInt(const std::string& text, int lo, int hi, int& value, std::string& why)
{
  why = DecimalSyntaxProblem(text, true);
  if (!why.empty())
  {
    return false;
  }
  errno = 0;
  const long long v = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE || v < lo || v > hi)
  {
    why = "out of range; must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

bool ParseDouble(const std::string& text, double lo, double hi, double& value, std::string& why)
{
  why = DecimalSyntaxProblem(text, false);
  if (!why.empty())
  {
    return false;
  }
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && std::fabs(v) > 1.0)
  {
    why = "too large to represent (beyond " + FormatNumber(DBL_MAX) + ", the largest double)";
    return false;
  }
  // Underflow: strtod returns a denormal or 0 with ERANGE. Refused rather than
  // rounded: the value the user wrote is not the value the program would use.
  if ((errno == ERANGE && std::fabs(v) < 1.0) || (v != 0.0 && std::fabs(v) < DBL_MIN))
  {
    why = "too small to represent: its magnitude is below " + FormatNumber(DBL_MIN) +
      ", the smallest normal double (it would be kept as a denormal or as 0); write 0 for zero";
    return false;
  }
  if (!(v >= lo && v <= hi))
  {
    why = "out of range; must be a number in [" + FormatNumber(lo) + ", " + FormatNumber(hi) + "]";
    return false;
  }
  value = v;
  return true;
}

bool ParseSize(const std::string& text, int& width, int& height, std::string& why)
{
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos)
  {
    why = "not WxH (two integers joined by x, e.g. 512x512)";
    return false;
  }
  std::string problem;
  if (!ParseInt(text.substr(0, x), 16, 8192, width, problem))
  {
    why = "width " + problem;
    return false;
  }
  if (!ParseInt(text.substr(x + 1), 16, 8192, height, problem))
  {
    why = "height " + problem;
    return false;
  }
  return true;
}
}
