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
uniform sampler3D st_volume;       // the mapper's own scalar texture
uniform float st_scalarScale;      // normalised scalar = texel * scale + bias
uniform float st_scalarBias;
uniform sampler2D st_medium;       // over the normalised scalar: rgb albedo (colour), a sigma_t per world unit
uniform float st_occlusionScale;  // OcclusionStrength: scales the attenuation along light paths only
uniform vec3 st_gridDims;
uniform vec3 st_gridToTex;
uniform vec3 st_gridToTexOffset;
uniform mat4 st_texToWorld;
uniform mat4 st_texToDataset;
uniform vec4 st_clipPlanes[6];     // world: kept where dot(n, p) + d >= 0
uniform int st_clipCount;
uniform int st_cropping;           // 1: cropping on
uniform int st_cropFlags;          // VTK's 27 region bits
uniform vec3 st_cropMin;           // dataset coordinates of the cropping planes
uniform vec3 st_cropMax;
uniform mat3 st_toSweep;           // grid axis order -> sweep texture order
uniform int st_masked;             // 1: a binary mask on the volume's grid
uniform int st_labelMasked;        // 1: a label-map mask: the medium's row is the label
uniform sampler3D st_mask;         // the mask (nearest, 8-bit): binary 0 = masked out, or labels
uniform float st_maskBlend;        // label-map mask: VTK's MaskBlendFactor
uniform float st_mediumRows;       // rows of st_medium (1, or 256 with a label-map mask)

vec3 st_gridToTexture(vec3 j)
{
  return j * st_gridToTex + st_gridToTexOffset;
}

// Normalised scalar (the transfer-function table coordinate) at a texture position.
float st_scalarAt(vec3 t)
{
  return texture(st_volume, t).r * st_scalarScale + st_scalarBias;
}

// Is the material at texture position t kept by the binary mask, the clipping
// planes and the cropping region? Removed material neither shows nor casts shadow.
bool st_kept(vec3 t)
{
  if (st_masked != 0 && texture(st_mask, t).r <= 0.0)
  {
    return false;
  }
  vec4 world = st_texToWorld * vec4(t, 1.0);
  for (int i = 0; i < st_clipCount; ++i)
  {
    if (dot(st_clipPlanes[i].xyz, world.xyz / world.w) + st_clipPlanes[i].w < 0.0)
    {
      return false;
    }
  }
  if (st_cropping != 0)
  {
    vec3 d = (st_texToDataset * vec4(t, 1.0)).xyz;
    ivec3 r = ivec3(step(st_cropMin, d)) + ivec3(step(st_cropMax, d));
    int region = r.x + 3 * r.y + 9 * r.z;
    if (((st_cropFlags >> region) & 1) == 0)
    {
      return false;
    }
  }
  return true;
}

// The medium at a texture position: rgb = albedo (the colour transfer function),
// a = extinction coefficient sigma_t per world unit in VTK's convention
// sigma_t = -ln(1 - alpha) / ScalarOpacityUnitDistance, tabulated on the CPU from
// the transfer functions the scene uses (scatterer/Transport.h). Removed or
// outside material: none.
vec4 st_mediumAt(vec3 t)
{
  if (any(lessThan(t, vec3(0.0))) || any(greaterThan(t, vec3(1.0))) || !st_kept(t))
  {
    return vec4(0.0);
  }
  float s = clamp(st_scalarAt(t), 0.0, 1.0);
  vec4 own = texture(st_medium, vec2(s, 0.5 / st_mediumRows));
  if (st_labelMasked != 0)
  {
    // Row = the label value (0: the volume's own transfer functions), mixed with row 0
    // by the blend factor as VTK mixes colour and opacity.
    float label = floor(texture(st_mask, t).r * 255.0 + 0.5);
    if (label > 0.0)
    {
      return mix(own, texture(st_medium, vec2(s, (label + 0.5) / st_mediumRows)), st_maskBlend);
    }
  }
  return own;
}

// The extinction that attenuates light on its way (the sweep): sigma_t times
// OcclusionStrength (1: physical; 0: no shadows, the medium still scatters).
float st_attenuationAt(vec3 t)
{
  return st_occlusionScale * st_mediumAt(t).a;
}

// Texture coordinate of grid position j in the transmittance texture.
vec3 st_sweepCoord(vec3 j)
{
  return st_toSweep * ((j + vec3(0.5)) / st_gridDims);
}
