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
// The slices carry T(p); the transmittance texture holds the texel's mean along the
// line, the mean of the light entering and leaving it:
//   T_texel = (T_in + T_out) / 2 = T(p) cosh(tau_half)
// with tau_half the optical depth from the texel's face toward the light to p, and the
// texel's far half taken as its near half (the sweep samples only between q and p).
// - Optically thin texel: T(p) to O(tau_half^2) (skin, opacity 0.1 per mm: about
//   1 % per texel).
// - Thick texel: T_in / 2. Bone (opacity 0.8 per mm) is several mean free paths deep
//   in one texel, and there T(p) = T_in exp(-tau_half) depends on where a surface
//   cuts the texel: it showed the grid as moire on a skull and streaks on a thin
//   dense plate. T_in / 2 is the light the view ray's samples get: a ray sees the
//   first mean free paths of a thick medium, lit at T_in exp(-s / mu_l), and weighted
//   as the ray composites them they average T_in mu_l / (mu_l + mu_v), T_in / 2
//   under the headlight (mu: cosines of the light's and the view's angles to the
//   surface).
// - Limit: a surface through p itself, with nothing in the near half, still reads
//   T_in there. Sampling the far half as well fixes that but makes the far side of a
//   thick texel read T_in / 2 too, light it does not get (tried: the shell + plate
//   benchmark scene moved from the reference, RMSE 0.0036 to 0.0043).
//
// A piece of a distributed volume (vtkScattererLightExchange): the light that enters
// what the piece holds (its voxels and ghost layers) has already crossed the pieces
// in front of it, whose optical depth beyond the ghost layers, tau_front, the
// light-space map st_enteringDepth holds (scatterer/LightSpace.h). By Beer-Lambert
// over the parts of the path,
//   T(p) = T_piece(p) * exp(-tau_front(line through p))
// The slices carry T_piece; the transmittance texture gets T (its texel mean).
//============================================================================
//VTK::Transport::Common
in vec2 texCoord;
uniform sampler2D st_previous;     // the slice swept before this one
uniform int st_hasPrevious;        // 0: first slice of a sweep, T = 1
uniform float st_slice;            // this slice's index along the sweep axis
uniform float st_sliceOrigin;      // the global index of slice 0 (grid texels)
uniform vec3 st_sweepDims;         // (rows, columns, slices) of the sweep texture
uniform mat3 st_worldToGrid;       // world vector -> grid-index vector
uniform mat3 st_gridToWorld;       // grid-index vector -> world vector
uniform vec3 st_lightToward;       // directional: unit vector toward the light (world)
uniform vec3 st_lightPosition;     // positional: world position
uniform int st_substeps;           // extinction samples per step (volume voxels per texel)
uniform mat4 st_texToIndex;        // volume texture coordinates -> structured index
uniform sampler2D st_enteringDepth;
uniform vec3 st_enteringLight;     // positional: the light (index space)
uniform vec3 st_enteringU;         // directional: the map plane's basis (index space)
uniform vec3 st_enteringV;
uniform vec2 st_enteringLo;        // directional: the map's corner on the plane
uniform float st_enteringSide;     // directional: the map's side (index units)

// The program comes in one variant per kind of light (ScattererTransportPrograms.cxx):
// ST_SWEEP_POSITIONAL (0: directional, 1: positional) and ST_SWEEP_ENTERING (the depth
// in front of a piece: 0 none, 1 a directional map, 2 a positional (octahedral) one).
// Mirrors scatterer::lightspace::Map::coordinate.
vec2 st_octahedral(vec3 d)
{
  vec2 p = d.xy / (abs(d.x) + abs(d.y) + abs(d.z));
  if (d.z < 0.0)
  {
    vec2 s = vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    p = (vec2(1.0) - abs(p.yx)) * s;
  }
  return p;
}

// The optical depth in front of this piece on the light's line through index i.
float st_depthInFront(vec3 i)
{
#if ST_SWEEP_ENTERING == 0
  return 0.0;
#else
#if ST_SWEEP_ENTERING == 2
  vec3 d = i - st_enteringLight;
  vec2 c = st_octahedral(length(d) > 0.0 ? normalize(d) : vec3(0.0, 0.0, 1.0)) * 0.5 + vec2(0.5);
#else
  vec2 c = (vec2(dot(i, st_enteringU), dot(i, st_enteringV)) - st_enteringLo) / st_enteringSide;
#endif
  return texture(st_enteringDepth, c).r;
#endif
}

void main()
{
  vec3 js = vec3(floor(texCoord * st_sweepDims.xy), st_slice);
  vec3 j = transpose(st_toSweep) * js;
  float T = 1.0;     // at the texel's centre p: carried to the next slice
  float Tmean = 1.0; // over the texel along the line: what the texture holds
  if (st_hasPrevious != 0)
  {
#if ST_SWEEP_POSITIONAL
    vec4 p = st_texToWorld * vec4(st_gridToTexture(j), 1.0);
    vec3 toward = st_lightPosition - p.xyz / p.w;
#else
    vec3 toward = st_lightToward;
#endif
    vec3 ds = st_toSweep * (st_worldToGrid * toward);
    // One slice toward the light; a light nearly in this slice's plane would
    // shift sideways without bound: at most 4 texels per step.
    float along = max(abs(ds.z), length(ds.xy) / 4.0);
    vec3 stepSweep = ds / max(along, 1.0e-20);
    stepSweep.z = sign(ds.z);
    vec3 qs = js + stepSweep;
    vec3 stepGrid = transpose(st_toSweep) * stepSweep;
    float len = length(st_gridToWorld * stepGrid);
    // Outside the grid the light has crossed no matter: the border reads 1.
#if ST_SWEEP_POSITIONAL
    float Tq = texture(st_previous, (qs.xy + vec2(0.5)) / st_sweepDims.xy).r;
    float Tcarried = Tq;
#else
    // The shifts e(z) of this slice and of the one before (see the top).
    vec2 a = stepSweep.xy * stepSweep.z;
    vec2 zj = vec2(js.z + st_sliceOrigin) * a;
    vec2 zq = vec2(qs.z + st_sliceOrigin) * a;
    vec2 ej = floor(zj + 0.5) - zj;
    vec2 eq = floor(zq + 0.5) - zq;
    float Tcarried =
      texture(st_previous, (floor(qs.xy + eq - ej + 0.5) + vec2(0.5)) / st_sweepDims.xy).r;
    float Tq = texture(st_previous, (qs.xy + eq + vec2(0.5)) / st_sweepDims.xy).r;
#endif
    // tau: the whole step q -> p; tauHalf: its part inside this texel, from the
    // texel's face toward the light (halfway to q) to p.
    float tau = 0.0;
    float tauHalf = 0.0;
    for (int i = 0; i < st_substeps; ++i)
    {
      float f = (float(i) + 0.5) / float(st_substeps);
      float a = st_attenuationAt(st_gridToTexture(j + stepGrid * f));
      tau += a;
      tauHalf += f < 0.5 ? a : (f == 0.5 ? 0.5 * a : 0.0); // a sample on the face: half
    }
    tau *= len / float(st_substeps);
    tauHalf *= len / float(st_substeps);
    T = Tcarried * exp(-tau);
    // The texel's mean light, (T_in + T_out) / 2 = T cosh(tauHalf), written with
    // exponents <= 0 (tauHalf <= tau): T cosh(tauHalf) overflows to 0 * inf in
    // opaque voxels hundreds of mean free paths deep.
    Tmean = 0.5 * Tq * (exp(tauHalf - tau) + exp(-tauHalf - tau));
  }
  gl_FragData[0] = vec4(T);
  vec3 index = (st_texToIndex * vec4(st_gridToTexture(j), 1.0)).xyz;
  gl_FragData[1] = vec4(Tmean * exp(-st_depthInFront(index)));
}
