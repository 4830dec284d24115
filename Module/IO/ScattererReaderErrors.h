// What VTK's readers report while vtkScattererVolumeReader runs them, caught instead of
// printed, so that a failed read becomes the reader's one-line error message: VTK's error
// events (ReaderErrorSink) and MetaIO's reports on std::cerr (CerrCapture).
#ifndef ScattererReaderErrors_h
#define ScattererReaderErrors_h

#include "vtkCallbackCommand.h"
#include "vtkNew.h"

#include <sstream>
#include <string>
#include <vector>

class vtkAlgorithm;

namespace scatterer_io
{
/**
 * Collects the errors a delegate reader reports instead of letting them print, as one
 * line: what the reader said, without VTK's source location and object address.
 */
class ReaderErrorSink
{
public:
  ReaderErrorSink();
  ReaderErrorSink(const ReaderErrorSink&) = delete;
  ReaderErrorSink& operator=(const ReaderErrorSink&) = delete;

  /** Observes the error events of @p algorithm and of its executive. */
  void Watch(vtkAlgorithm* algorithm);
  bool Failed() const { return this->ExecutiveFailed || !this->Messages.empty(); }
  /** The messages joined with "; ". */
  std::string Text() const;

private:
  void Add(std::string text);

  std::vector<std::string> Messages;
  bool ExecutiveFailed = false;
  vtkNew<vtkCallbackCommand> Command;
};

/**
 * MetaIO (inside vtkMetaImageReader) reports read errors such as "Uncompress failed" or
 * "data not read completely" only on std::cerr, and goes on with a partly filled volume.
 * While a MetaImage is read, std::cerr is redirected here so that such a report fails the
 * read. (std::cerr is process-wide: output of other threads in that moment lands here too.)
 */
class CerrCapture
{
public:
  CerrCapture();
  ~CerrCapture();
  CerrCapture(const CerrCapture&) = delete;
  CerrCapture& operator=(const CerrCapture&) = delete;

  /** The reports, one line; MetaIO's deprecation notes are not errors. */
  std::string Errors() const;

private:
  std::ostringstream Buffer;
  std::streambuf* Previous;
};
}

#endif
