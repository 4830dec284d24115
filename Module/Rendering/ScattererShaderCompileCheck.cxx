#include "ScattererShaderCompileCheck.h"

#include "ScattererShaderComposer.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"

namespace scatterer_render
{
namespace
{
bool IsIlluminationProgram(vtkShaderProgram* program)
{
  vtkShader* fragment = program ? program->GetFragmentShader() : nullptr;
  return fragment &&
    fragment->GetSource().find(scatterer_shader::kProgramMarker) != std::string::npos;
}
}

ShaderCompileCheck::ShaderCompileCheck()
{
  this->Catcher->SetClientData(&this->Errors);
  this->Catcher->SetCallback(
    [](vtkObject*, unsigned long, void* client, void* call)
    {
      static_cast<std::vector<std::string>*>(client)->push_back(
        call ? static_cast<const char*>(call) : "");
    });
}

ShaderCompileCheck::~ShaderCompileCheck()
{
  if (this->Mapper && this->Tag)
  {
    this->Mapper->RemoveObserver(this->Tag);
  }
}

void ShaderCompileCheck::Begin(vtkOpenGLRenderWindow* window, vtkObject* mapper)
{
  this->Window = window;
  this->Mapper = mapper;
  this->Errors.clear();
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  vtkShaderProgram* last = cache->GetLastShaderBound();
  if (last && last->GetHandle() != 0)
  {
    // Unbinds it (the ray caster binds its own program anyway).
    cache->ReleaseCurrentShader();
  }
  else
  {
    cache->ClearLastShaderBound();
  }
  this->Tag = mapper->AddObserver(vtkCommand::ErrorEvent, this->Catcher);
}

bool ShaderCompileCheck::End()
{
  this->Mapper->RemoveObserver(this->Tag);
  this->Tag = 0;
  vtkShaderProgram* bound = this->Window->GetShaderCache()->GetLastShaderBound();
  if (!bound)
  {
    // Nothing was bound since Begin: either the ray caster had no program to draw with
    // (it failed to compile, and the ray caster raised an error), or it drew nothing this
    // frame (an empty or invisible input: no error). Only the first is a failure.
    return this->Errors.empty();
  }
  if (bound->GetCompiled() && (bound == this->Confirmed || IsIlluminationProgram(bound)))
  {
    this->Confirmed = bound;
    return true;
  }
  // Another program was bound after the ray cast (VTK's resampling quad when
  // ImageSampleDistance != 1) and hides the ray cast's program, which VTK 9.1 gives
  // no other access to (it lives in vtkOpenGLGPUVolumeRayCastMapper's private
  // vtkInternal, and the mapper fires no event with it when it builds a shader):
  // only the ray caster's error text tells.
  for (const auto& e : this->Errors)
  {
    if (e.find("Shader failed to compile") != std::string::npos)
    {
      return false;
    }
  }
  return true;
}
}
