// A volume whose image direction matrix mirrors (determinant < 0), and what VTK 9.1's ray
// caster needs to draw it.
//
// vtkOpenGLGPUVolumeRayCastMapper draws the front faces of the volume's bounding box
// (culling GL_BACK, vtkVolumeStateRAII) and starts each ray there. It orders the box's
// triangles by the sign of the determinant of the vtkVolume's matrix
// (RenderVolumeGeometry), but not by that of the image's direction matrix, which also
// places the box's corners. A direction that mirrors reverses the triangles' winding on
// screen: the back faces are drawn instead, every ray starts where it should end, and
// only slivers of the volume show (measured: stock shows a box's edges and none of a
// ball inside it). While such a volume renders, the winding OpenGL takes as front-facing
// is reversed (glFrontFace(GL_CW)), which undoes exactly that reversal.
//
// The reversal would also cull the full-screen quad with which VTK draws a frame
// rendered at ImageSampleDistance != 1 (EndImageSample), so those frames render at the
// full image resolution (ImageSampleDistanceFor).
//
// Not undone: while the camera's near plane cuts through the box, VTK clips the box there
// (vtkClipConvexPolyData, which takes the mirrored box's faces for facing inwards) and
// keeps the wrong side; nothing is drawn, by the stock mapper either. The mapper says so
// (NearPlaneCutsVolume).
#ifndef ScattererMirroredWinding_h
#define ScattererMirroredWinding_h

class vtkDataObject;
class vtkRenderer;
class vtkVolume;

namespace scatterer_render
{
/**
 * True when @p vol renders @p input through a box whose winding VTK 9.1 gets wrong: an
 * image (not a vtkMultiVolume, whose box is laid out in world coordinates) whose direction
 * matrix has a negative determinant.
 */
bool DirectionMirrors(vtkVolume* vol, vtkDataObject* input);

/**
 * True when the near plane of @p ren's camera cuts through the box of @p input's points
 * as @p vol places it (points on both sides of it, or on it), as VTK 9.1 decides that the
 * camera is inside the volume.
 */
bool NearPlaneCutsVolume(vtkRenderer* ren, vtkVolume* vol, vtkDataObject* input);

/** The image sample distance a frame can render at: 1 where @p mirrors, else @p requested. */
float ImageSampleDistanceFor(bool mirrors, float requested);

/** Reverses the front-facing winding (GL_CW) for its lifetime where @p mirrors. */
class ScopedMirroredWinding
{
public:
  explicit ScopedMirroredWinding(bool mirrors);
  ~ScopedMirroredWinding();
  ScopedMirroredWinding(const ScopedMirroredWinding&) = delete;
  ScopedMirroredWinding& operator=(const ScopedMirroredWinding&) = delete;

private:
  bool Mirrors;
};
}

#endif
