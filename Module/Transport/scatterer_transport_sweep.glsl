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
// interpolated once, from the slice before at q + e(z_q), where it holds T(q). Left:
// Beer-Lambert over each step is sampled along the texel's own segment, not the
// shifted line's, so an occluder's imprint keeps its slice's e (at most half a texel).
// Positional lights keep the bilinear read: their lines diverge, no shift serves a
// whole slice.
//
// The slices carry T(p); the transmittance texture holds the light entering the texel,
// at its face toward the light:
//   T_in = T(q) exp(-tau_far)
// tau_far the optical depth from q to that face (st_stepFactors). In a thin texel that
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
// ST_SWEEP_POSITIONAL (0: directional, 1: positional) and ST_SWEEP_ENTERING
// (scatterer_transport_sweep_common.glsl).
void main()
{
  vec3 js = vec3(floor(texCoord * st_sweepDims.xy), st_slice);
  vec3 j = transpose(st_toSweep) * js;
  float T = 1.0;         // at the texel's centre p: carried to the next slice
  float Tentering = 1.0; // entering the texel: what the texture holds
  if (st_hasPrevious != 0)
  {
#if ST_SWEEP_POSITIONAL
    vec4 p = st_texToWorld * vec4(st_gridToTexture(j), 1.0);
    vec3 stepSweep, stepGrid;
    float len;
    st_stepTowardLight(st_lightPosition - p.xyz / p.w, stepSweep, stepGrid, len);
#else
    vec3 stepSweep = st_stepSweep, stepGrid = st_stepGrid;
    float len = st_stepLength;
#endif
    vec3 qs = js + stepSweep;
    // Outside the grid the light has crossed no matter: the border reads 1.
#if ST_SWEEP_POSITIONAL
    float Tq = texture(st_previous, (qs.xy + vec2(0.5)) / st_sweepDims.xy).r;
    float Tcarried = Tq;
#else
    // The shifts e(z) of this slice and of the one before (see the top).
    vec2 a = stepSweep.xy * stepSweep.z;
    vec2 ej = st_sliceShift(js.z, a);
    vec2 eq = st_sliceShift(qs.z, a);
    float Tcarried =
      texture(st_previous, (floor(qs.xy + eq - ej + 0.5) + vec2(0.5)) / st_sweepDims.xy).r;
    float Tq = texture(st_previous, (qs.xy + eq + vec2(0.5)) / st_sweepDims.xy).r;
#endif
    float tau, tauHalf;
    st_stepDepth(j, stepGrid, len, tau, tauHalf);
    float enteringFactor;
    T = Tcarried * st_stepFactors(tau, tauHalf, enteringFactor);
    Tentering = Tq * enteringFactor;
  }
  gl_FragData[0] = vec4(T);
  gl_FragData[1] = vec4(st_storedTransmittance(Tentering, j));
}
