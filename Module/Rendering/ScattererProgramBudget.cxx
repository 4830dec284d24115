#include "ScattererProgramBudget.h"

#include "ScattererShaderComposer.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <list>
#include <map>
#include <mutex>

namespace scatterer_shader
{
namespace
{
// Per window, its illumination programs, most recently used first. Weak
// pointers: the window's shader cache owns the programs and deletes them with it.
using Recent = std::list<vtkWeakPointer<vtkShaderProgram>>;
struct Registry
{
  std::mutex Mutex;
  std::map<vtkOpenGLRenderWindow*, std::pair<vtkWeakPointer<vtkOpenGLRenderWindow>, Recent>>
    Windows;
};

Registry& TheRegistry()
{
  static Registry registry;
  return registry;
}

bool IsIlluminationProgram(vtkShaderProgram* program)
{
  vtkShader* fragment = program ? program->GetFragmentShader() : nullptr;
  return fragment && fragment->GetSource().find(kProgramMarker) != std::string::npos;
}

// The entry of a live window (a window deleted and another allocated at its
// address starts afresh).
Recent& Entry(Registry& registry, vtkOpenGLRenderWindow* window)
{
  auto& entry = registry.Windows[window];
  if (entry.first != window)
  {
    entry.first = window;
    entry.second.clear();
  }
  return entry.second;
}
}

void NoteProgramUse(vtkOpenGLRenderWindow* window, vtkShaderProgram* program)
{
  if (!window || !program)
  {
    return;
  }
  Registry& registry = TheRegistry();
  std::lock_guard<std::mutex> lock(registry.Mutex);
  Recent& recent = Entry(registry, window);
  // Most frames draw with the program of the frame before: no need to search its
  // source text (tens of KB) for the marker again.
  if (!recent.empty() && recent.front() == program)
  {
    return;
  }
  if (!IsIlluminationProgram(program))
  {
    return;
  }
  recent.remove_if(
    [program](const vtkWeakPointer<vtkShaderProgram>& p) { return p == nullptr || p == program; });
  recent.emplace_front(program);
  bool released = false;
  while (static_cast<int>(recent.size()) > kCompiledProgramsPerWindow)
  {
    vtkShaderProgram* oldest = recent.back();
    recent.pop_back();
    if (oldest && oldest->GetCompiled())
    {
      oldest->ReleaseGraphicsResources(window);
      released = true;
    }
  }
  if (released)
  {
    // vtkShaderProgram::ReleaseGraphicsResources unbinds whatever program GL has
    // bound (glUseProgram(0)), while the cache still records it as bound and so
    // would not bind it again: tell the cache that nothing is bound.
    window->GetShaderCache()->ReleaseCurrentShader();
  }
}

int CountCompiledIlluminationPrograms(vtkOpenGLRenderWindow* window)
{
  Registry& registry = TheRegistry();
  std::lock_guard<std::mutex> lock(registry.Mutex);
  const Recent& recent = Entry(registry, window);
  return static_cast<int>(std::count_if(recent.begin(), recent.end(),
    [](const vtkWeakPointer<vtkShaderProgram>& p) { return p && p->GetCompiled(); }));
}
}
