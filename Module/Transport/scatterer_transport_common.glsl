//============================================================================
// Light transport volume (ScattererTemplate): what the sweep and the gather
// passes share. Prepended to both fragment shaders.
//
// Grid conventions. The transport grid has st_gridDims texels (volume texture
// axis order); texel j sits at the volume texture coordinate
//   t(j) = j * st_gridToTex.xyz + st_gridToTexOffset
// (texel 0 on the first data point, texel M-1 on the last one), and in the world
// at st_texToWorld * vec4(t, 1): the ray caster's own placement of the volume
// (its dataset matrix, the image direction matrix and the volume's user matrix).
// The per-light transmittance texture st_transmittance is stored with the sweep
// axis last: st_toSweep maps a grid position to its (row, column, slice).
//============================================================================
uniform sampler3D st_volume;       // the mapper's own scalar texture (1-4 components)
uniform vec4 st_scalarScale;       // normalised scalar = texel * scale + bias, per component
uniform vec4 st_scalarBias;
uniform int st_components;         // components of st_volume
uniform vec4 st_componentWeights;  // independent components: vtkVolumeProperty's weights
uniform vec3 st_voxelStep;         // 2D transfer function: one texel of st_volume
uniform vec3 st_gradientAspect;    // 2D transfer function: spacing * 2 / mean spacing per axis
uniform sampler2D st_medium;       // over the normalised scalar: rgb albedo (colour), a sigma_t per world unit
uniform sampler1D st_extinction;   // st_medium's sigma_t of row 0 alone (st_attenuationAt)
uniform float st_occlusionScale;  // OcclusionStrength: scales the attenuation along light paths only
uniform vec3 st_gridDims;
uniform vec3 st_gridToTex;
uniform vec3 st_gridToTexOffset;
uniform mat4 st_texToWorld;
uniform mat4 st_texToDataset;
uniform vec4 st_clipPlanes[6];     // world: kept where dot(n, p) + d >= 0
uniform int st_clipCount;
uniform int st_cropFlags;          // VTK's 27 region bits
uniform vec3 st_cropMin;           // dataset coordinates of the cropping planes
uniform vec3 st_cropMax;
uniform mat3 st_toSweep;           // grid axis order -> sweep texture order
uniform sampler3D st_mask;         // the mask (nearest, 8-bit): binary 0 = masked out, or labels
uniform float st_maskBlend;        // label-map mask: VTK's MaskBlendFactor
uniform float st_mediumRows;       // rows of st_medium (1, or 256 with a label-map mask)

// The component rules (vtkScattererTransportVolume::Inputs::ComponentRule). The
// program defines ST_COMPONENT_MODE (the rule) and ST_MATERIAL_COMPONENT (the component
// the material table is over) in front of this text (ScattererTransportPrograms.cxx):
// one program per rule, so that one scalar pays nothing for the others. So are
// ST_MASK (ST_NO_MASK, ST_BINARY_MASK, ST_LABEL_MASK), ST_CROPPING (0, 1) and
// ST_CLIPPING (0, 1: clipping planes): a branch on a uniform does not spare what it
// skips on Mesa's llvmpipe, which runs both sides for a whole group of pixels. With
// these and the sweep's own variants (the light's kind) a sweep of the CT head, which
// has no mask, went from 97 to 52 ms on 2 cores; without clipping planes the clipping
// test (a world position per sample) cost a sweep another fifth.
#define ST_ONE_SCALAR 0
#define ST_INDEPENDENT 1
#define ST_LUMINANCE_ALPHA 2
#define ST_RGBA 3
#define ST_TRANSFER_2D 4
#define ST_MULTI_INPUT 5
#define ST_NO_MASK 0
#define ST_BINARY_MASK 1     // a voxel whose mask value is 0 is masked out
#define ST_LABEL_MASK 2      // a label map: the medium's row is the label

vec3 st_gridToTexture(vec3 j)
{
  return j * st_gridToTex + st_gridToTexOffset;
}

// Normalised scalars (the transfer-function table coordinates) at a texture position.
vec4 st_scalarsAt(vec3 t)
{
  return clamp(texture(st_volume, t) * st_scalarScale + st_scalarBias, 0.0, 1.0);
}

// The normalised scalar that selects the material (the material table's coordinate).
float st_scalarAt(vec3 t)
{
#if ST_COMPONENT_MODE == ST_ONE_SCALAR || ST_COMPONENT_MODE == ST_TRANSFER_2D
  return clamp(texture(st_volume, t).r * st_scalarScale.x + st_scalarBias.x, 0.0, 1.0);
#else
  return st_scalarsAt(t)[ST_MATERIAL_COMPONENT];
#endif
}

// Is the material at texture position t kept by the binary mask, the clipping
// planes and the cropping region? Removed material neither shows nor casts shadow.
bool st_kept(vec3 t)
{
#if ST_MASK == ST_BINARY_MASK
  if (texture(st_mask, t).r <= 0.0)
  {
    return false;
  }
#endif
#if ST_CLIPPING
  vec4 world = st_texToWorld * vec4(t, 1.0);
  for (int i = 0; i < st_clipCount; ++i)
  {
    if (dot(st_clipPlanes[i].xyz, world.xyz / world.w) + st_clipPlanes[i].w < 0.0)
    {
      return false;
    }
  }
#endif
#if ST_CROPPING
  vec3 d = (st_texToDataset * vec4(t, 1.0)).xyz;
  ivec3 r = ivec3(step(st_cropMin, d)) + ivec3(step(st_cropMax, d));
  int region = r.x + 3 * r.y + 9 * r.z;
  if (((st_cropFlags >> region) & 1) == 0)
  {
    return false;
  }
#endif
  return true;
}

// Row `row` of the medium table at normalised scalar s.
vec4 st_mediumRow(float s, float row)
{
  return texture(st_medium, vec2(s, (row + 0.5) / st_mediumRows));
}

#if ST_COMPONENT_MODE != ST_ONE_SCALAR
// The gradient magnitude a 2D transfer function is looked up at, as VTK 9.1's ray caster
// computes it (computeGradient): central differences of the scalar over one texel, each
// axis divided by its spacing aspect, over a quarter of the scalar range, clamped to 1.
// In normalised scalars the range cancels.
float st_gradientMagnitudeAt(vec3 t)
{
  vec3 d;
  for (int a = 0; a < 3; ++a)
  {
    vec3 step = vec3(0.0);
    step[a] = st_voxelStep[a];
    d[a] = (texture(st_volume, t + step).r - texture(st_volume, t - step).r) * st_scalarScale.x;
  }
  return clamp(length(d / st_gradientAspect) / 0.25, 0.0, 1.0);
}

// The medium of several components at their normalised scalars s, as VTK's ray caster
// makes colour and opacity of them (vtkVolumeShaderComposer, 9.1).
vec4 st_componentsMedium(vec4 s)
{
#if ST_COMPONENT_MODE == ST_LUMINANCE_ALPHA
  return vec4(st_mediumRow(s.x, 0.0).rgb, st_mediumRow(s.y, 1.0).a);
#elif ST_COMPONENT_MODE == ST_RGBA
  return vec4(s.rgb, st_mediumRow(s.w, 0.0).a);
#else
  // Independent components: VTK composites a step with opacity
  //   A = sum_c alpha_c^2 / sum_c w_c alpha_c   (numerator over components with w_c > 0)
  // and premultiplied colour sum_c w_c alpha_c rgb_c. Over a short step d,
  // alpha_c = sigma_c d, so the mix is a medium with
  //   sigma_t = sum_c sigma_c^2 / sum_c w_c sigma_c,
  //   albedo  = sum_c w_c sigma_c rgb_c / sigma_t   (clamped to 1 where components overlap),
  // which is one component's own medium where the others are empty.
  float total = 0.0, squares = 0.0;
  vec3 colour = vec3(0.0);
  for (int c = 0; c < 4; ++c)
  {
    if (c >= st_components)
    {
      break;
    }
    vec4 m = st_mediumRow(s[c], float(c));
    float w = st_componentWeights[c];
    total += w * m.a;
    if (w > 0.0)
    {
      squares += m.a * m.a;
      colour += w * m.a * m.rgb;
    }
  }
  if (!(total > 0.0) || !(squares > 0.0))
  {
    return vec4(0.0);
  }
  float sigma = squares / total;
  return vec4(clamp(colour / sigma, 0.0, 1.0), sigma);
#endif
}
#endif

#if ST_COMPONENT_MODE == ST_MULTI_INPUT
// A vtkMultiVolume's inputs (ST_PARTS of them, defined with the rule): the grid lies on
// a box that holds them all, and t is the box's texture coordinate.
uniform sampler3D st_parts[ST_PARTS];
uniform mat4 st_boxToPart[ST_PARTS];   // box texture coordinate -> the part's own
uniform vec2 st_partScaleBias[ST_PARTS]; // texel -> normalised scalar: * x + y

// Part k's medium at box position t: row k of the medium at its normalised scalar s;
// none outside the part (inside: false).
vec4 st_partMedium(sampler3D volume, int k, vec3 t, out float s, out bool inside)
{
  vec3 p = (st_boxToPart[k] * vec4(t, 1.0)).xyz;
  s = 0.0;
  inside = all(greaterThanEqual(p, vec3(0.0))) && all(lessThanEqual(p, vec3(1.0)));
  if (!inside)
  {
    return vec4(0.0);
  }
  s = clamp(texture(volume, p).r * st_partScaleBias[k].x + st_partScaleBias[k].y, 0.0, 1.0);
  return st_mediumRow(s, float(k));
}

// The parts together. VTK 9.1 composites them one after the other at each ray step, so
// a step's opacity is 1 - prod_k (1 - alpha_k): the extinctions add,
//   sigma_t = sum_k sigma_k,  albedo = sum_k sigma_k rgb_k / sigma_t.
// `dominant` is the part that takes the most light at t (-1: none), `scalar` its scalar:
// it gives the material there (st_materialCoordAt). Where no part has matter, the albedo
// is the first covering part's colour there, as one volume's medium keeps its colour
// transfer function's value where the opacity is 0 (the diffusion's coarse grid averages
// it in: scatterer_transport_coarsen.glsl), so that a volume alone and the same volume
// in a vtkMultiVolume are lit alike.
vec4 st_multiMedium(vec3 t, out int dominant, out float scalar)
{
  float sigma = 0.0, most = 0.0;
  vec3 colour = vec3(0.0), emptyColour = vec3(0.0);
  bool covered = false;
  dominant = -1;
  scalar = 0.0;
  // Samplers in an array take constant indices only: one block per part.
  // (one line: GLSL 1.50 has no line continuation)
#define ST_ADD_PART(k) { float s; bool inside; vec4 m = st_partMedium(st_parts[k], k, t, s, inside); sigma += m.a; colour += m.a * m.rgb; if (m.a > most) { most = m.a; dominant = k; scalar = s; } if (inside && !covered) { covered = true; emptyColour = m.rgb; } }
  ST_ADD_PART(0)
#if ST_PARTS > 1
  ST_ADD_PART(1)
#endif
#if ST_PARTS > 2
  ST_ADD_PART(2)
#endif
#if ST_PARTS > 3
  ST_ADD_PART(3)
#endif
  return sigma > 0.0 ? vec4(clamp(colour / sigma, 0.0, 1.0), sigma) : vec4(emptyColour, 0.0);
}
#endif

// Is there a medium at texture position t: inside the volume and kept?
bool st_inMedium(vec3 t)
{
  return all(greaterThanEqual(t, vec3(0.0))) && all(lessThanEqual(t, vec3(1.0))) && st_kept(t);
}

// The medium at a texture position: rgb = albedo (the colour transfer function),
// a = extinction coefficient sigma_t per world unit in VTK's convention
// sigma_t = -ln(1 - alpha) / ScalarOpacityUnitDistance, tabulated on the CPU from
// the transfer functions the scene uses (scatterer/Transport.h). Removed or
// outside material: none.
vec4 st_mediumAt(vec3 t)
{
  if (!st_inMedium(t))
  {
    return vec4(0.0);
  }
#if ST_COMPONENT_MODE == ST_MULTI_INPUT
  int dominant;
  float s;
  return st_multiMedium(t, dominant, s);
#elif ST_COMPONENT_MODE == ST_TRANSFER_2D
  return texture(st_medium, vec2(st_scalarAt(t), st_gradientMagnitudeAt(t)));
#elif ST_COMPONENT_MODE != ST_ONE_SCALAR
  return st_componentsMedium(st_scalarsAt(t));
#else
  float s = st_scalarAt(t);
  vec4 own = st_mediumRow(s, 0.0);
#if ST_MASK == ST_LABEL_MASK
  // Row = the label value (0: the volume's own transfer functions), mixed with row 0
  // by the blend factor as VTK mixes colour and opacity.
  float label = floor(texture(st_mask, t).r * 255.0 + 0.5);
  if (label > 0.0)
  {
    return mix(own, st_mediumRow(s, label), st_maskBlend);
  }
#endif
  return own;
#endif
}

// Point k of n^3 spread evenly over texel j, in grid index units.
vec3 st_texelPoint(vec3 j, int k, int n)
{
  vec3 s = vec3(float(k % n), float((k / n) % n), float(k / (n * n)));
  return j + (s + vec3(0.5)) / float(n) - vec3(0.5);
}

// Where the material table is read for the matter at texture position t (inside the
// grid and kept): (normalised scalar, row); row < 0: no matter, no material.
vec2 st_materialCoordAt(vec3 t)
{
#if ST_COMPONENT_MODE == ST_MULTI_INPUT
  // The part that takes the most light there gives the material, from its own row.
  int dominant;
  float s;
  st_multiMedium(t, dominant, s);
  return dominant < 0 ? vec2(0.0, -1.0) : vec2(s, (float(dominant) + 0.5) / float(ST_PARTS));
#else
  return vec2(clamp(st_scalarAt(t), 0.0, 1.0), 0.5);
#endif
}

// The extinction that attenuates light on its way (the sweep): sigma_t times
// OcclusionStrength (1: physical; 0: no shadows, the medium still scatters).
// One scalar without a label map reads sigma_t from st_extinction, a one-channel 1D copy
// of st_medium's alpha (TransportTables::Upload): the sweeps, most of a rebuild under
// several lights, read it for each step's near half (pass 0a for the texels' means of
// the far halves), and a linear read of one channel in 1D is a fraction of the filtering
// of a 2D RGBA one (on llvmpipe a light kit's sweeps took 2-12 % less time, the same
// values: docs/rendering.md).
float st_attenuationAt(vec3 t)
{
#if ST_COMPONENT_MODE == ST_ONE_SCALAR && ST_MASK != ST_LABEL_MASK
  return st_inMedium(t) ? st_occlusionScale * texture(st_extinction, st_scalarAt(t)).r : 0.0;
#else
  return st_occlusionScale * st_mediumAt(t).a;
#endif
}

// Texture coordinate of grid position j in the transmittance texture.
vec3 st_sweepCoord(vec3 j)
{
  return st_toSweep * ((j + vec3(0.5)) / st_gridDims);
}
