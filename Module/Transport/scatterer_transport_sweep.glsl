//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 1: transmittance sweep (one slice per draw).
//
// Light propagation slice by slice along the light's dominant grid axis
// (Behrens & Ratering 1998; Ropinski et al. 2010): a texel of slice k takes the
// transmittance of slice k -/+ 1 where the line toward the light crosses it, and
// multiplies it by Beer-Lambert over the step between the two:
//   T(p) = T(q) * exp(-integral_q^p sigma_t ds)          (Beer-Lambert)
// so T holds the fraction of the light's energy that reaches p through the whole
// volume, in O(N) per light. Directional lights: one direction for all texels.
// Positional lights: the direction toward the light per texel, and slices are
// swept away from the light's own slice on both sides (the radial variant).
//
// Directional lights: the light is carried without numerical diffusion. Reading the
// slice before at q by bilinear interpolation, slice after slice, blurs a shadow edge
// like a random walk: after n slices over about sqrt(n f (1 - f)) texels, f the
// fractional part of the sideways step (3 texels, 6 voxels, on the benchmark's plate
// 30 slices from the shell, and sharp or blurred as the light turns). So the slices
// carry T along lines that keep to whole texels: slice z is the light's field shifted
// sideways by e(z) = round(z a) - z a, a the sideways step per slice (|e| <= 1/2, the
// same for the whole slice; z the global slice index, so that pieces of a distributed
// volume agree), i.e. a texel c of slice z carries T(c - e(z)), read from the texel
//   c + round(z_q a) - round(z a)            (a whole texel: no interpolation)
// of the slice before (z_q), which holds T(. - e(z_q)). What the texture stores is
// interpolated once, from the slice before at q + e(z_q), where it holds T(q).
// Beer-Lambert over each step is sampled along the line's own path, through its point
// c - e(z) in each slice: the near half from there, the far half's factor where the line
// crossed the slice before (st_farFactor, kept there beside T). Sampled along the texel's
// segment through c instead (until 2026-12-06), an occluder's imprint kept its slice's e
// (at most half a texel), and an oblique light drew stripes along the sweep on a smooth
// surface (scatterer_transport_lines.glsl). Positional lights keep the bilinear read:
// their lines diverge, no shift serves a whole slice.
//
// The slices carry T(p); the transmittance texture holds the light entering the texel,
// at its face toward the light:
//   T_in = T(q) exp(-tau_far)
// tau_far the optical depth from q to that face (st_farFactor; a directional light's
// T(q) and factor both interpolated at q from the lines' points). In a thin texel that
// is T(p) to O(tau_half) (skin, opacity 0.1 per mm: about 10 % per texel). In a dense one
// (bone, opacity 0.8 per mm, is several mean free paths deep in one texel) T(p) =
// T_in exp(-tau_half) depends on where a surface cuts the texel, and it drew the grid
// on dense surfaces (moire on a skull, streaks on a plate, terraces on a ball). T_in
// does not: it is the light that reaches the texel's matter, whatever depth the
// surface lies at inside it. The texels behind a dense surface hold hardly any light;
// the gather weights the interior ones down so that a ray's read at the surface takes
// the surface's texels (scatterer_transport_gather.glsl). Left: a ray composites the
// first mean free paths of a dense medium, lit at T_in exp(-s / mu_l), to
// T_in mu_l / (mu_l + mu_v) (mu: cosines of the light's and the view's angles to the
// surface), T_in / 2 under the headlight; the read gives them T_in. Against the Monte
// Carlo reference T_in came closer on all five accuracy scenes than the texel's mean
// along the line, (T_in + T_out) / 2, which gave T_in / 2 in dense texels and the grid's
// layers as terraces (docs/model.md).
//
// A piece of a distributed volume (vtkScattererLightExchange): the light that enters
// what the piece holds (its voxels and ghost layers) has already crossed the pieces
// in front of it, whose optical depth beyond the ghost layers, tau_front, the
// light-space map st_enteringDepth holds (scatterer/LightSpace.h). By Beer-Lambert
// over the parts of the path,
//   T(p) = T_piece(p) * exp(-tau_front(line through p))
// The slices carry T_piece; the transmittance texture gets T (the light entering the
// texel).
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Sweep
in vec2 texCoord;
uniform sampler2D st_previous;     // the slice swept before this one
uniform int st_hasPrevious;        // 0: first slice of a sweep, T = 1
uniform float st_slice;            // this slice's index along the sweep axis
uniform vec3 st_lightPosition;     // positional: world position

// The program comes in one variant per kind of light (ScattererTransportPrograms.cxx):
// ST_SWEEP_POSITIONAL (0: directional, 1: positional), ST_SWEEP_ENTERING and
// ST_SWEEP_ONE_SAMPLE (scatterer_transport_sweep_common.glsl).
void main()
{
  vec3 js = vec3(floor(texCoord * st_sweepDims.xy), st_slice);
  vec3 j = transpose(st_toSweep) * js;
  float T = 1.0;         // at the line's point: carried to the next slice
  float Tentering = 1.0; // entering the texel: what the texture holds
#if ST_SWEEP_POSITIONAL
  vec4 world = st_texToWorld * vec4(st_gridToTexture(j), 1.0);
  vec3 toLight = st_lightPosition - world.xyz / world.w;
  vec3 stepSweep, stepGrid;
  float len;
  st_stepTowardLight(toLight, stepSweep, stepGrid, len);
  // The slice before holds this texel's path to the light only if the light lies
  // beyond it: not in a run's first slice (a light inside the grid lies in or beside
  // it), nor where the path runs more than 4 texels sideways a slice (the step's cap),
  // near the light's own slice. And within 3 slices of the light the slice before is
  // read too near the light, where T has its kink: read between texels there, every
  // path that converges on the light took on about a texel's optical depth too much.
  // There the light is marched to through the grid. Taken as 1 (until 2026-12-07), the
  // light's own slices were lit through any matter.
  // A marched texel takes the light where a swept one does, at the end of its step's
  // near half: the step one slice toward the light along the path, its near half at most
  // 2 texels sideways (the sweep's cap, 4 texels a step), the rest of the step from the
  // texels' means on the slice toward the light (st_farMeanExtinction), and T(q) marched
  // from the step's end q. So a marched texel beside a swept one takes the light as it
  // does. Taken at the texel's nearest face with the volume's own points (until
  // 2026-12-07, night), a texel whose path ran flat through a dense surface (the top
  // texels of a plate a few voxels under the light, beyond 4 texels sideways a slice)
  // crossed up to two texels of its matter that a swept texel beside it takes as the
  // texels' mean at q: a ring of dark scallops around the lit disc where the two met
  // (docs/hard-cases.md).
  vec3 toLightGrid = st_worldToGrid * toLight;
  vec3 toLightSweep = st_toSweep * toLightGrid;
  float slices = abs(toLightSweep.z);
  float steps = st_stepsAlong(toLightSweep); // more than slices: capped sideways
  if (st_hasPrevious == 0 || slices < 3.0 || steps > slices)
  {
    // The share of the way to the light in the near half: half a step, at most 2 texels
    // sideways (1 where the light lies in the near half).
    float nearShare = min(0.5 / max(steps, 1.0e-6), 1.0);
    // Where the march starts (fraction `from` of the way from there) and the optical
    // depth of the step's far part beyond the near part. One march and one sample of the
    // near part (st_nearDepthToLight): llvmpipe runs this branch's reads, masked, for
    // every fragment of the draw, swept ones included (docs/rendering.md).
    vec3 start = j;
    vec3 startToLight = toLightGrid;
    float from = nearShare;
    float tauFar = 0.0;
    if (slices >= 1.0)
    {
      vec3 pathStep = toLightGrid / slices;
      float near = nearShare * slices; // of the step
      start = j + pathStep;
      startToLight = toLightGrid - pathStep;
      from = 0.0;
      tauFar = (1.0 - near) * length(st_gridToWorld * pathStep) *
        st_farMeanExtinction(j, pathStep, near);
    }
    Tentering = exp(-st_depthToLight(start, startToLight, from) - tauFar);
    T = Tentering * exp(-st_nearDepthToLight(j, toLightGrid, nearShare));
  }
  else
  {
    // Outside the grid the light has crossed no matter: the border reads 1.
    float Tq = texture(st_previous, (js.xy + stepSweep.xy + vec2(0.5)) / st_sweepDims.xy).r;
    Tentering = Tq * st_farFactor(j + stepGrid, stepGrid, len);
    T = Tentering * exp(-st_nearHalfDepth(j, stepGrid, len));
  }
  gl_FragData[0] = vec4(T, 1.0, 0.0, 0.0);
#else
  // The shifts e(z) of this slice and of the one before, and the line's point in this
  // slice, c - e(z) (see the top).
  vec2 a = st_stepSweep.xy * st_stepSweep.z;
  vec2 ej = st_sliceShift(js.z, a);
  vec3 p = transpose(st_toSweep) * (js - vec3(ej, 0.0));
  if (st_hasPrevious != 0)
  {
    vec3 qs = js + st_stepSweep;
    vec2 eq = st_sliceShift(qs.z, a);
    // The line's T at its texel in the slice before (a whole texel; outside the grid the
    // border reads 1: no matter), times its step: the far half's factor at its point
    // there, p + stepGrid, taken again rather than read back in half precision (as the
    // lines keep it: scatterer_transport_lines.glsl), and the near half.
    vec2 before = floor(qs.xy + eq - ej + 0.5);
    float far = all(greaterThanEqual(before, vec2(0.0))) && all(lessThan(before, st_sweepDims.xy))
      ? st_farFactor(p + st_stepGrid, st_stepGrid, st_stepLength)
      : 1.0;
    T = texture(st_previous, (before + vec2(0.5)) / st_sweepDims.xy).r * far *
      exp(-st_nearHalfDepth(p, st_stepGrid, st_stepLength));
    // At q, (T, st_farFactor) between the lines' points.
    Tentering =
      st_lightEnteringTexel(texture(st_previous, (qs.xy + eq + vec2(0.5)) / st_sweepDims.xy).rg, j);
  }
  gl_FragData[0] = vec4(T, st_farFactor(p, st_stepGrid, st_stepLength), 0.0, 0.0);
#endif
  gl_FragData[1] = vec4(st_storedTransmittance(Tentering, j));
}
