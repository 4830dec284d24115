// Internal: number formatting for error messages ("got nan", "got -0.5").
#pragma once

#include <cmath>
#include <sstream>
#include <string>

namespace scatterer {
namespace detail {

inline std::string describe(double value)
{
  if (std::isnan(value)) {
    return "NaN";
  }
  std::ostringstream s;
  s.precision(17);
  s << value;
  return s.str();
}

} // namespace detail
} // namespace scatterer
