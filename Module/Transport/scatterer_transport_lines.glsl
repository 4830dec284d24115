//VTK::System::Dec
#extension GL_ARB_shader_image_load_store : require
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 1 for a directional light, its lines in parallel
// (a few draws): what scatterer_transport_sweep.glsl computes slice after slice, one
// draw per slice, each fragment here computes along one line through the slices.
//
// The slices carry the light along lines that keep to whole texels (the top of
// scatterer_transport_sweep.glsl): texel c of slice z takes the light of texel
//   c + round(z_q a) - round(z a)
// of the slice before, z_q. So c - round(z a) is the same all along a line: the line's
// index k. A line needs nothing from the others, and one fragment per line carries
//   T(p_z) = T(p_zq) exp(-tau(p_z))                      (Beer-Lambert)
// from the first slice (T = 1) away from the light, as the slices do, with T = 1 where
// the line's texel in the slice before lies outside the grid (the border the slice
// sweep reads). p_z = k + z a = c - e(z) is the line's own point in slice z, the point
// whose light texel c holds, and tau is sampled along the line's own path: its near half
// from p_z (st_nearHalfDepth), its far half the factor kept at p_zq (st_farFactor).
// Sampled along the texel's segment through c instead (until 2026-12-06), an occluder's
// imprint kept each slice's shift, and an oblique light drew stripes along the sweep on
// a smooth surface (Benchmarks/accuracy/ring_probe.py: 7.3 % of its brightness; 1.6 %
// now). It stores T and st_farFactor per texel (image load/store: one fragment writes
// every slice of its line). The light entering a texel is the light between lines at
// its q (interpolated at q + e(z_q)), so a second, layered draw computes it
// (scatterer_transport_line_texels.glsl) every few draws of the lines, for their slices
// (the lines' texture holds those and the slice before them: st_lineSlot). The lines go
// st_chunkSlices slices a draw, each draw taking up T where the one before left it
// (st_lineStart) and covering only the lines with a texel in the grid in its slices: the
// lines of an oblique light that cross the grid somewhere are several times a slice's
// texels (2.5 times at 511x511x215 under the benchmark's headlight), and a draw of them
// all ran most of them idle. A handful of draws per light instead of one per slice: on
// a GPU a draw costs more than a slice's fragments.
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Sweep
in vec2 texCoord;
// Per texel (T, st_farFactor) at the line's point, sweep order, a ring of slices
// (st_lineSlot).
layout(rg16f) writeonly uniform image3D st_lines;
uniform vec2 st_lineOrigin;     // the index k of pixel 0 (the draws cover what they need)
uniform float st_firstSlice;    // the sweep's first slice (nearest the light)
uniform int st_chunkFirst;      // this draw's slices: st_chunkFirst, ... (in sweep order)
uniform int st_chunkSlices;
// Per line, (T, the step it was left at) by the draw before that drew the line: a line
// the draw before did not draw had no texel in the grid there, and enters it now (T = 1).
uniform sampler2D st_lineStart;

// Line k in step i of the sweep (away from the light): its slice z, its texel there, c
// = k + round(z a), and its point p = k + z a (grid order); whether c lies in the grid
// returned.
bool st_linePoint(vec2 k, int i, out float z, out vec2 c, out vec3 p)
{
  z = st_firstSlice - float(i) * st_stepSweep.z; // the slices follow each other away from the light
  vec2 za = st_sliceOffset(z, st_stepSweep.xy * st_stepSweep.z);
  c = k + st_sliceTexels(za);
  p = transpose(st_toSweep) * vec3(k + za, z);
  return all(greaterThanEqual(c, vec2(0.0))) && all(lessThan(c, st_sweepDims.xy));
}

void main()
{
  // The draws cover parts of the lines' texture (glViewport): the pixel is gl_FragCoord's.
  // texCoord is read only to keep the attribute VTK's quad binds (vtkOpenGLQuadHelper
  // reports an error for a program without it); it never exceeds 1.
  if (texCoord.x > 2.0)
  {
    discard;
  }
  vec2 pixel = floor(gl_FragCoord.xy);
  vec2 k = pixel + st_lineOrigin;
  vec2 start = texelFetch(st_lineStart, ivec2(pixel), 0).rg;
  float T = st_chunkFirst > 0 && start.g == float(st_chunkFirst) ? start.r : 1.0;
  int end = min(st_chunkFirst + st_chunkSlices, int(st_sweepDims.z));
  float z;
  vec2 c;
  vec3 p;
  // The far half's factor at the line's point in the slice before (1 outside the grid,
  // where there is no matter, as the slice sweep's border): this draw's first step takes
  // it up there, the others from the step before.
  float farBefore = 1.0;
  if (st_chunkFirst > 0 && st_linePoint(k, st_chunkFirst - 1, z, c, p))
  {
    farBefore = st_farFactor(p, st_stepGrid, st_stepLength);
  }
  for (int i = st_chunkFirst; i < end; ++i)
  {
    if (!st_linePoint(k, i, z, c, p))
    {
      T = 1.0; // outside the grid the light has crossed no matter
      farBefore = 1.0;
      continue;
    }
    if (i > 0)
    {
      T *= farBefore * exp(-st_nearHalfDepth(p, st_stepGrid, st_stepLength));
    }
    farBefore = st_farFactor(p, st_stepGrid, st_stepLength);
    imageStore(st_lines, ivec3(ivec2(c), st_lineSlot(z)), vec4(T, farBefore, 0.0, 0.0));
  }
  gl_FragData[0] = vec4(T, float(end), 0.0, 1.0);
}
