// libFuzzer target: volume headers (docs/fuzzing.md).
//
// The input is written as a MetaImage, NRRD or NIfTI file (VolumeHeaderInput.h) in a
// folder of this process and goes through the header check
// (Module/IO/ScattererVolumeHeaderCheck.cxx). Whatever the check accepts is then read by
// vtkScattererVolumeReader::ReadVolume, i.e. by VTK 9.1's own readers (the system VTK,
// not instrumented; only this project's sources are). Findings:
//   - any crash, sanitizer report, uncaught exception, timeout or allocation past the
//     limits (VTK's readers crash on bad headers the check lets through);
//   - a refusal whose message is empty, spans lines or does not name the file;
//   - ReadVolume refusing what the check refused with a different problem;
//   - a volume that differs from what the check predicted (the reader refuses it with
//     "VTK's reader delivered ..."): the check's model of the VTK reader is wrong there;
//   - a delivered volume with non-finite or non-positive spacing or a non-finite origin.
// A VTK error on a file the check accepted (say a gzip stream damaged past the part the
// check decodes) is allowed: it is reported as such, naming the file.
// The files live in a folder made under $TMPDIR and removed at exit; after a crash it
// stays, which is why scripts/fuzz.sh points TMPDIR into its own work folder.
#include "FuzzCommon.h"
#include "VolumeHeaderInput.h"

#include "ScattererVolumeHeaderCheck.h"
#include "vtkScattererVolumeReader.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

// VTK's warnings (say "Unknown field" from vtkNrrdReader) would be printed for millions
// of inputs. Errors still reach the reader's observers: vtkObject's global warning
// display stays on, only the window that prints (and VTK's logger) are silent.
class SilentOutputWindow : public vtkOutputWindow {
public:
  static SilentOutputWindow* New();
  vtkTypeMacro(SilentOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
};
vtkStandardNewMacro(SilentOutputWindow);

std::string folder;

void removeFolder()
{
  std::error_code ec;
  std::filesystem::remove_all(folder, ec);
}

void write(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  FUZZ_CHECK(out.good(), "cannot write %s", path.c_str());
}

bool oneLineNaming(const std::string& message, const std::string& path)
{
  return !message.empty() && message.find('\n') == std::string::npos &&
         message.find("'" + path + "'") != std::string::npos;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  std::string pattern =
    (std::filesystem::temp_directory_path() / "scatterer-fuzz-headers.XXXXXX").string();
  FUZZ_CHECK(mkdtemp(&pattern[0]) != nullptr, "cannot create a folder under %s",
    std::filesystem::temp_directory_path().c_str());
  folder = pattern;
  std::atexit(removeFolder);
  vtkNew<SilentOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // VTK 9.1 also logs each warning

  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const fuzz::VolumeFiles files = fuzz::decodeVolumeInput(data, size);
  // Files of earlier inputs must not be found by this one's header.
  for (const char* name :
    { "v.mha", "v.mhd", "v.nrrd", "v.nhdr", "v.nii", "v.nii.gz", "data.raw" }) {
    std::filesystem::remove(folder + "/" + name);
  }
  const std::string path = folder + "/" + files.headerName;
  write(path, files.header);
  if (files.detached) {
    write(folder + "/data.raw", files.data);
  }

  scatterer_io::HeaderCheck check;
  switch (files.format) {
  case fuzz::kMetaImageLocal:
  case fuzz::kMetaImageDetached:
    check = scatterer_io::CheckMetaImageHeader(path);
    break;
  case fuzz::kNrrdAttached:
  case fuzz::kNrrdDetached:
    check = scatterer_io::CheckNrrdHeader(path);
    break;
  default:
    check = scatterer_io::CheckNiftiHeader(path);
    break;
  }
  const bool accepted = check.Problem.empty();
  FUZZ_CHECK(accepted || check.Problem.find('\n') == std::string::npos, "multi-line problem: %s",
    check.Problem.c_str());
  if (accepted) {
    const scatterer_io::VolumeLayout& l = check.Layout;
    FUZZ_CHECK(scatterer_io::CheckLayout(l).empty(), "accepted an unsound layout: %s",
      scatterer_io::CheckLayout(l).c_str());
    // The fuzzer's memory limit, not the product's: a header may rightly promise a volume
    // larger than the 1 GiB libFuzzer allows (a raw file named by absolute path, say).
    const double values =
      double(l.Dimensions[0]) * l.Dimensions[1] * l.Dimensions[2] * l.Components;
    if (values > 16.0 * 1024 * 1024) {
      return 0;
    }
  }

  std::string error;
  vtkSmartPointer<vtkImageData> image = vtkScattererVolumeReader::ReadVolume(path, &error);
  if (!accepted) {
    FUZZ_CHECK(!image, "ReadVolume read a file the check refused: %s", check.Problem.c_str());
    FUZZ_CHECK(error.find(check.Problem) != std::string::npos,
      "ReadVolume's message '%s' is not the check's '%s'", error.c_str(), check.Problem.c_str());
  }
  if (!image) {
    FUZZ_CHECK(oneLineNaming(error, path), "bad message: %s", error.c_str());
    // The reason follows the first "': " (after the file's path), so header text quoted
    // later in a message cannot pose as this one.
    const std::size_t reason = error.find("': ");
    FUZZ_CHECK(
      reason == std::string::npos || error.compare(reason + 3, 22, "VTK's reader delivered") != 0,
      "the check mispredicted VTK's reader: %s", error.c_str());
    return 0;
  }
  FUZZ_CHECK(error.empty(), "error set on success: %s", error.c_str());
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  FUZZ_CHECK(scalars && scalars->GetNumberOfTuples() == image->GetNumberOfPoints(),
    "scalars do not cover the grid");
  for (int i = 0; i < 3; ++i) {
    FUZZ_CHECK(dims[i] == check.Layout.Dimensions[i], "dimension %d: %d, predicted %d", i, dims[i],
      check.Layout.Dimensions[i]);
    const double s = image->GetSpacing()[i];
    FUZZ_CHECK(std::isfinite(s) && s > 0, "spacing %d is %g", i, s);
    FUZZ_CHECK(std::isfinite(image->GetOrigin()[i]), "origin %d is %g", i, image->GetOrigin()[i]);
  }
  FUZZ_CHECK(scalars->GetNumberOfComponents() == check.Layout.Components,
    "%d components, predicted %d", scalars->GetNumberOfComponents(), check.Layout.Components);
  return 0;
}
