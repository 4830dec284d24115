// Whether the stock ray caster drew a frame with the illumination program, or found
// that the program does not compile on this OpenGL implementation.
//
// VTK 9.1's ray caster keeps its shader program in its private vtkInternal and
// reports a failed compile only as the error text "Shader failed to compile". What
// its public API does show is the window's vtkOpenGLShaderCache: ReadyShaderProgram
// binds a program only after it compiled (vtkShaderProgram::GetCompiled), and records
// it as the cache's LastShaderBound. So the check forgets the last bound program
// before the ray caster renders and reads it afterwards: a compiled illumination
// program means it compiled and drew; no program bound, with an error raised, means
// the compile failed (no program and no error: the ray caster drew nothing).
//
// One case the API cannot see: with ImageSampleDistance != 1, VTK draws its
// resampling quad with another program after the ray cast, which hides the program
// the ray cast used (or its absence), and VTK 9.1 offers no other way to it. For those
// frames only, the check falls back to the ray caster's error text.
#ifndef ScattererShaderCompileCheck_h
#define ScattererShaderCompileCheck_h

#include "vtkNew.h"
#include "vtkShaderProgram.h" // for vtkWeakPointer<vtkShaderProgram>
#include "vtkWeakPointer.h"

#include <string>
#include <vector>

class vtkCallbackCommand;
class vtkObject;
class vtkOpenGLRenderWindow;

namespace scatterer_render
{
/**
 * Brackets the ray caster's render and tells whether its illumination program
 * compiled, through the window's shader cache (see above for the one exception).
 */
class ShaderCompileCheck
{
public:
  ShaderCompileCheck();
  ~ShaderCompileCheck();
  ShaderCompileCheck(const ShaderCompileCheck&) = delete;
  ShaderCompileCheck& operator=(const ShaderCompileCheck&) = delete;

  /**
   * Just before the ray caster renders in @p window: forgets the program the shader
   * cache last bound, and holds back the errors raised on @p mapper until End.
   */
  void Begin(vtkOpenGLRenderWindow* window, vtkObject* mapper);

  /** Just after: false when the illumination program failed to compile. */
  bool End();

  /**
   * The errors held back during the render. After a failed compile they are the
   * ray caster's report of it, which the mapper replaces by its own, clearer error;
   * otherwise they are raised again as they were.
   */
  const std::vector<std::string>& GetErrors() const { return this->Errors; }

private:
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkObject* Mapper = nullptr;
  unsigned long Tag = 0;
  // The illumination program last seen to draw: most frames draw with it again, and
  // need not search its source text (tens of KB) for the marker.
  vtkWeakPointer<vtkShaderProgram> Confirmed;
  std::vector<std::string> Errors;
  vtkNew<vtkCallbackCommand> Catcher;
};
}

#endif
