// Shared helpers for the GoogleTest programs that render: one render window
// for the whole program (opening X connections one after another can fail
// under Xvfb), pixel read-back, image comparisons and event counting.
#ifndef ScattererRenderHarness_h
#define ScattererRenderHarness_h

#include "vtkCallbackCommand.h"
#include "vtkNew.h"

#include <string>
#include <vector>

class vtkAbstractMapper;
class vtkLight;
class vtkObject;
class vtkRenderer;
class vtkRenderWindow;

namespace scatterer_testing
{
/** The program's one render window (160x160, no multisampling). */
vtkRenderWindow* SharedWindow();

/** Renders the window and returns its RGBA pixels. */
std::vector<unsigned char> RenderAndGrab(vtkRenderWindow* window);

/**
 * Renders @p renderer alone in the shared window and returns its RGBA pixels; then takes
 * the renderer out again and releases @p mapper's graphics resources, so that the next
 * scene starts afresh.
 */
std::vector<unsigned char> RenderSceneOnce(vtkRenderer* renderer, vtkAbstractMapper* mapper);

/**
 * Adds a white directional scene light to @p renderer that shines from @p position
 * towards @p focalPoint, and returns it (the renderer holds it).
 */
vtkLight* AddSceneLight(vtkRenderer* renderer, double px, double py, double pz, double fx = 0.0,
  double fy = 0.0, double fz = 0.0);

/**
 * The ball-above-a-plate scenes' light and camera (an @p n ^3 grid of unit spacing, the
 * plate near its floor): lit from above and a little to the side, so that the ball's
 * shadow falls on the plate beside the ball, where the camera sees it.
 */
void LightAndViewBallAbovePlate(vtkRenderer* renderer, int n);

/** OpenGL errors raised since the last call (0 = none); clears them. */
unsigned int TakeGLError();

/** Largest channel difference (256 if the sizes differ). */
int MaxDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b);

/** Writes RGBA pixels of a w x h image to a PNG (to look at a failure). */
void SavePng(const std::string& path, const std::vector<unsigned char>& rgba, int w, int h);

/** How two RGBA images of the same size differ, on their RGB channels. */
struct ImageDifference
{
  double Mean = 0.0;         // mean absolute channel difference (levels of 255)
  double FractionOver = 0.0; // fraction of pixels with a channel more than `levels` off
  int Worst = 0;             // largest channel difference
  size_t Pixels = 0;         // pixels compared
};

/**
 * Compares @p a and @p b (RGBA). With @p include, only the pixels where it is
 * true count (one entry per pixel). Sizes must match (Worst 256 otherwise).
 */
ImageDifference CompareRgb(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
  int levels, const std::vector<bool>* include = nullptr);

/**
 * One scene rendered two ways (say whole and partitioned), each lit and stock: how the
 * two lit pictures differ, how the two stock ones do (what the ray caster itself
 * changes), and how lit differs from stock (whether the illumination shows at all);
 * channel differences over 16 levels count as over. Prints the three under @p what.
 */
struct Equivalence
{
  ImageDifference Lit, Stock, Illumination;
};
Equivalence CompareWays(const char* what, const std::vector<unsigned char>& litA,
  const std::vector<unsigned char>& litB, const std::vector<unsigned char>& stockA,
  const std::vector<unsigned char>& stockB);

/** Mean of the RGB channels. */
double MeanBrightness(const std::vector<unsigned char>& image);

/**
 * Counts events of one kind on an object and keeps the last call data as text (for
 * events such as UpdateShaderEvent; errors and warnings: vtkTest::ErrorObserver with
 * Testing/Common/ScattererErrorObserver.h).
 */
struct EventCounter
{
  int Count = 0;
  std::string Last;
  vtkNew<vtkCallbackCommand> Command;
  EventCounter(vtkObject* object, unsigned long event);
};
}

#endif
