// A NRRD header read the way vtkNrrdReader 9.1 reads it, for ScattererNrrdHeaderCheck.cxx:
// the reader's count of axes changes as it goes, so the fields are parsed in order.
#ifndef ScattererNrrdHeaderFields_h
#define ScattererNrrdHeaderFields_h

#include <map>
#include <string>
#include <vector>

namespace scatterer_io
{
namespace header_check
{
struct NrrdFields
{
  // Where attached data starts: after the first empty line; -1 without one (a detached
  // header, or a file that ends in its header).
  long long HeaderBytes = -1;
  // "<name>: <value>" as written (vtkNrrdReader neither trims nor lowercases the name;
  // the value is trimmed). Key/value pairs ("<key>:=<value>") and comments are not here.
  std::map<std::string, std::string> Fields;
  int Dimension = 0;                    // the "dimension" field; 0 if there is none
  std::vector<long long> Sizes;         // one per axis, each in [1, INT_MAX]
  std::vector<double> Spacing;          // per axis, from spacings or space directions
  bool SpacingIsDirections = false;     // Spacing holds the lengths of space directions
  double Origin[3] = { 0.0, 0.0, 0.0 }; // space origin, up to three numbers
};

/**
 * Reads the header at headerPath into *header. Returns the problem (one sentence) when
 * the file is no NRRD header vtkNrrdReader reads safely, empty otherwise.
 */
std::string ReadNrrdFields(const std::string& headerPath, NrrdFields* header);
}
}

#endif
