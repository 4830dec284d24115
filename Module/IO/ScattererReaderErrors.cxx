#include "ScattererReaderErrors.h"

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"

#include <algorithm>
#include <iostream>

namespace scatterer_io
{
//------------------------------------------------------------------------------
ReaderErrorSink::ReaderErrorSink()
{
  this->Command->SetClientData(this);
  this->Command->SetCallback([](vtkObject*, unsigned long, void* client, void* call)
    { static_cast<ReaderErrorSink*>(client)->Add(call ? static_cast<const char*>(call) : ""); });
}

void ReaderErrorSink::Add(std::string text)
{
  // VTK's messages read "ERROR: In <file>, line N\n<vtkClass> (0x..): <text>\n\n".
  if (text.compare(0, 10, "ERROR: In ") == 0 && text.find('\n') != std::string::npos)
  {
    text = text.substr(text.find('\n') + 1);
  }
  const auto prefix = text.find("): ");
  if (prefix != std::string::npos && prefix < text.find('\n') && text.find(" (0x") < prefix)
  {
    text = text.substr(prefix + 3);
  }
  // The executive's "Algorithm ... returned failure for request: <vtkInformation dump>"
  // only repeats that the reader failed; its dump runs over many lines.
  if (text.find("returned failure for request") != std::string::npos)
  {
    this->ExecutiveFailed = true;
    return;
  }
  text = text.substr(0, text.find('\n'));
  while (!text.empty() && (text.back() == ' ' || text.back() == '\r' || text.back() == '.'))
  {
    text.pop_back();
  }
  if (text.empty())
  {
    text = "unknown error";
  }
  if (std::find(this->Messages.begin(), this->Messages.end(), text) == this->Messages.end())
  {
    this->Messages.push_back(text);
  }
}

std::string ReaderErrorSink::Text() const
{
  if (this->Messages.empty())
  {
    return "VTK's reader failed without saying why";
  }
  std::string joined;
  for (const std::string& message : this->Messages)
  {
    joined += (joined.empty() ? "" : "; ") + message;
  }
  return joined;
}

void ReaderErrorSink::Watch(vtkAlgorithm* algorithm)
{
  algorithm->AddObserver(vtkCommand::ErrorEvent, this->Command);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Command);
}

//------------------------------------------------------------------------------
CerrCapture::CerrCapture()
  : Previous(std::cerr.rdbuf(this->Buffer.rdbuf()))
{
}

CerrCapture::~CerrCapture()
{
  std::cerr.rdbuf(this->Previous);
}

std::string CerrCapture::Errors() const
{
  std::istringstream lines(this->Buffer.str());
  std::string line;
  std::string errors;
  while (std::getline(lines, line))
  {
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line.find("deprecated") != std::string::npos)
    {
      continue;
    }
    line = line.substr(b, line.find_last_not_of(" \t\r") - b + 1);
    errors += (errors.empty() ? "" : " ") + line;
  }
  return errors;
}
}
