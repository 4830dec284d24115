//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 2: template in-scattering (one layer per draw,
// one draw per light, added up by blending).
//
// The light a point p of material m receives from light l (irradiance E_l):
//   R_l(p) = E_l a_l(p) sum_j w_j c_j T_l(p + r_j) / sum_j w_j      (single scattering)
// - r_j, w_j: the photons of material m's scatterer templates (Lee, Kwon, Shin
//   2016, Eq. 1-5), all templates merged, in mean free paths of m (the paper's
//   lambda) converted to world units (scatterer/Transport.h).
// - c_j: 1 for a photon in m; the colour of material mp for a photon in another
//   material (colour bleeding, section 3.3). Such a photon's offset is rescaled by
//   the speed ratio n_m / n_mp and its weight by the opacity ratio (section 3.4).
// - a_l(p): VTK's attenuation and spot cone of a positional light, 1 otherwise.
// A second output collects the source of multiple scattering, the light scattered
// once at p: S(p) = sigma_t(p) albedo(p) sum_l E_l a_l(p) T_l(p)  (the diffusion
// passes spread it: scatterer_transport_diffuse.glsl).
//============================================================================
//VTK::Transport::Common
in vec2 texCoord;
#define ST_MAX_MATERIALS 8
uniform sampler3D st_transmittance;
uniform sampler2D st_kernel;       // row m: (offset in world units, weight), st_kernelCount wide
uniform int st_kernelCount;
uniform float st_layer;
uniform mat3 st_worldToGrid;
uniform int st_materialCount;
uniform sampler2D st_materialTable; // material index over the normalised scalar (a row per part), -1: none
uniform vec3 st_matColor[ST_MAX_MATERIALS];
uniform float st_speedRatio[ST_MAX_MATERIALS * ST_MAX_MATERIALS];
uniform float st_opacityRatio[ST_MAX_MATERIALS * ST_MAX_MATERIALS];
uniform int st_bleed;
uniform int st_boundary;
uniform vec3 st_lightColor;
uniform vec3 st_lightPosition;
uniform vec3 st_lightFocalDirection; // positional: unit vector from the light to its focal point
uniform int st_lightPositional;
uniform vec3 st_lightAttenuation;
uniform float st_lightConeCos;       // cos(cone angle); <= -1: no cone
uniform float st_lightExponent;

int st_materialAt(vec3 t)
{
  if (any(lessThan(t, vec3(0.0))) || any(greaterThan(t, vec3(1.0))) || !st_kept(t))
  {
    return -1;
  }
  vec2 at = st_materialCoordAt(t);
  return at.y < 0.0 ? -1 : int(floor(texture(st_materialTable, at).r + 0.5));
}

float st_T(vec3 j)
{
  return texture(st_transmittance, st_sweepCoord(j)).r;
}

void main()
{
  vec3 j = vec3(floor(texCoord * st_gridDims.xy), st_layer);
  vec3 t = st_gridToTexture(j);
  int m = st_materialAt(t);
  vec3 single = vec3(st_T(j));
  if (m >= 0)
  {
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    // Only bleeding and the boundary rescale need the material at each photon.
    bool lookAtPhotons = st_materialCount > 1 && (st_bleed != 0 || st_boundary != 0);
    for (int k = 0; k < st_kernelCount; ++k)
    {
      vec4 photon = texelFetch(st_kernel, ivec2(k, m), 0);
      vec3 offset = st_worldToGrid * photon.xyz;
      float w = photon.w;
      vec3 tint = vec3(1.0);
      if (lookAtPhotons)
      {
        int mp = st_materialAt(st_gridToTexture(j + offset));
        if (st_boundary != 0 && mp >= 0 && mp != m)
        {
          offset *= st_speedRatio[m * ST_MAX_MATERIALS + mp];
          w *= st_opacityRatio[m * ST_MAX_MATERIALS + mp];
          mp = st_materialAt(st_gridToTexture(j + offset));
        }
        tint = (st_bleed != 0 && mp >= 0 && mp != m) ? st_matColor[mp] : vec3(1.0);
      }
      sum += w * tint * st_T(j + offset);
      weights += photon.w;
    }
    single = weights > 0.0 ? sum / weights : single;
  }
  float a = 1.0;
  if (st_lightPositional != 0)
  {
    vec4 p = st_texToWorld * vec4(t, 1.0);
    vec3 fromLight = p.xyz / p.w - st_lightPosition;
    float d = length(fromLight);
    a = 1.0 / max(dot(st_lightAttenuation, vec3(1.0, d, d * d)), 1.0e-6);
    if (st_lightConeCos > -1.0)
    {
      float c = dot(fromLight / max(d, 1.0e-20), st_lightFocalDirection);
      a *= c < st_lightConeCos ? 0.0 : pow(max(c, 0.0), st_lightExponent);
    }
  }
  gl_FragData[0] = vec4(a * st_lightColor * single, 1.0);
  vec4 medium = st_mediumAt(t);
  gl_FragData[1] = vec4(medium.a * medium.rgb * a * st_lightColor * st_T(j), 1.0);
}
