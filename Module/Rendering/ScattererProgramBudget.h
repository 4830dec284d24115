// A bound on the illumination programs kept compiled per render window.
//
// VTK keeps every shader program it ever compiled in the window's
// vtkOpenGLShaderCache until the window goes away. Each switch of an effect,
// of the illumination mode or of shading asks for another illumination shader
// text, and on llvmpipe one compiled illumination program holds about 3 MB: a
// user toggling effects grew a process by hundreds of MiB (issue 13). This
// keeps the most recently used kCompiledProgramsPerWindow illumination programs
// of a window compiled and releases the graphics resources (the compiled code)
// of older ones. VTK compiles a released program again when a mapper next binds
// it. What stays in VTK's cache is the program's source text, bounded by the
// finite set of illumination texts (the texts do not depend on the number of
// lights or materials; scatterer_illumination_dec.glsl).
#ifndef ScattererProgramBudget_h
#define ScattererProgramBudget_h

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

namespace scatterer_shader
{
/** Illumination programs a window keeps compiled (the rest are released, least recently used
 * first). */
constexpr int kCompiledProgramsPerWindow = 8;

/**
 * Records that @p program drew an illuminated volume in @p window (ignored
 * unless it is an illumination program), then releases the compiled code of
 * this window's least recently used illumination programs beyond the bound.
 */
void NoteProgramUse(vtkOpenGLRenderWindow* window, vtkShaderProgram* program);

/** Illumination programs of @p window that are compiled now (for tests). */
int CountCompiledIlluminationPrograms(vtkOpenGLRenderWindow* window);
}

#endif
