//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 2b: template in-scattering (one layer per draw, once
// for all lights).
//
// The light a point p of material m receives, scattered once, from the light arriving
// unscattered around it (A = sum_l E_l a_l T_l: scatterer_transport_arriving.glsl):
//   R(p) = sum_j w_j c_j A(p + r_j) / sum_j w_j                     (single scattering)
// - r_j, w_j: the photons of material m's scatterer templates (Lee, Kwon, Shin
//   2016, Eq. 1-5), all templates merged, in mean free paths of m (the paper's
//   lambda) converted to world units (scatterer/Transport.h).
// - c_j: 1 for a photon in m; the colour of material mp for a photon in another
//   material (colour bleeding, section 3.3). Such a photon's offset is rescaled by
//   the speed ratio n_m / n_mp and its weight by the opacity ratio (section 3.4).
// A point outside every material receives A(p) itself.
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Arriving
in vec2 texCoord;
#define ST_MAX_MATERIALS 8
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

int st_materialAt(vec3 t)
{
  if (any(lessThan(t, vec3(0.0))) || any(greaterThan(t, vec3(1.0))) || !st_kept(t))
  {
    return -1;
  }
  vec2 at = st_materialCoordAt(t);
  return at.y < 0.0 ? -1 : int(floor(texture(st_materialTable, at).r + 0.5));
}

void main()
{
  vec3 j = vec3(floor(texCoord * st_gridDims.xy), st_layer);
  vec3 t = st_gridToTexture(j);
  int m = st_materialAt(t);
  vec3 single = st_arrivingAt(j);
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
      sum += w * tint * st_arrivingAt(j + offset);
      weights += photon.w;
    }
    single = weights > 0.0 ? sum / weights : single;
  }
  gl_FragData[0] = vec4(single, 1.0);
}
