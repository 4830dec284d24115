// Error and warning checks on top of VTK's vtkTest::ErrorObserver (vtkTestErrorObserver.h),
// which keeps the text of every ErrorEvent / WarningEvent of the objects it observes, one
// after the other (an observer also keeps VTK from printing them). VTK 9.1 starts each
// message with "ERROR: In " / "Warning: In " (file and line), so the messages can still be
// counted and the last one taken apart.
#ifndef ScattererErrorObserver_h
#define ScattererErrorObserver_h

#include "vtkAlgorithm.h"
#include "vtkExecutive.h"
#include "vtkTestErrorObserver.h"

#include <cstddef>
#include <string>

namespace scatterer_testing
{
/** Observes the ErrorEvents of @p algorithm and of its executive (failed requests). */
inline void WatchErrors(vtkAlgorithm* algorithm, vtkTest::ErrorObserver* errors)
{
  algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
}

namespace detail
{
inline std::size_t CountOf(const std::string& text, const std::string& start)
{
  std::size_t n = 0;
  for (std::size_t at = text.find(start); at != std::string::npos; at = text.find(start, at + 1))
  {
    ++n;
  }
  return n;
}

inline std::string LastOf(const std::string& text, const std::string& start)
{
  const std::size_t at = text.rfind(start);
  return at == std::string::npos ? std::string() : text.substr(at);
}
}

/** How many error messages @p errors holds (since it was made or cleared). */
inline std::size_t ErrorCount(vtkTest::ErrorObserver* errors)
{
  return detail::CountOf(errors->GetErrorMessage(), "ERROR: In ");
}

/** How many warning messages @p warnings holds (since it was made or cleared). */
inline std::size_t WarningCount(vtkTest::ErrorObserver* warnings)
{
  return detail::CountOf(warnings->GetWarningMessage(), "Warning: In ");
}

/** The last error message ("" if none). */
inline std::string LastError(vtkTest::ErrorObserver* errors)
{
  return detail::LastOf(errors->GetErrorMessage(), "ERROR: In ");
}

/** The last warning message ("" if none). */
inline std::string LastWarning(vtkTest::ErrorObserver* warnings)
{
  return detail::LastOf(warnings->GetWarningMessage(), "Warning: In ");
}

/** Whether any error message @p errors holds contains @p text. */
inline bool ErrorMentions(vtkTest::ErrorObserver* errors, const std::string& text)
{
  return errors->GetErrorMessage().find(text) != std::string::npos;
}
}

#endif
