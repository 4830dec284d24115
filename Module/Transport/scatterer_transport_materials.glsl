//============================================================================
// The materials and their scatterer templates, as the medium pass (0a) and the
// template gather (2b) read them: the material at a point, each material's photons
// (Lee, Kwon, Shin 2016, Eq. 1-5) and the tables of section 3.3 (colour bleeding)
// and 3.4 (Snell speed ratio, opacity ratio). Inserted after the common declarations.
// ST_MAX_MATERIALS comes with the variant's defines (scatterer_scene::kMaxMaterials).
//============================================================================
// The medium pass marks a texel some of whose photons land in another material by its
// material + ST_MIXED (scatterer_transport_medium.glsl).
#define ST_MIXED ST_MAX_MATERIALS
// The gather's variants (ST_GATHER, defined per program: scatterer_gpu::GatherVariant).
#define ST_GATHER_ARRIVING 0
#define ST_GATHER_TEMPLATES 1
#define ST_GATHER_ACROSS_MATERIALS 2
// Row m: material m's photons (offset in world units, weight), st_kernelCount of them,
// then the kernel's centroid (offset, weight 1).
uniform sampler2D st_kernel;
uniform int st_kernelCount;
uniform mat3 st_worldToGrid;
uniform int st_materialCount;
uniform sampler2D st_materialTable; // material index over the normalised scalar (a row per part), -1: none
uniform vec3 st_matColor[ST_MAX_MATERIALS];
uniform float st_speedRatio[ST_MAX_MATERIALS * ST_MAX_MATERIALS];
uniform float st_opacityRatio[ST_MAX_MATERIALS * ST_MAX_MATERIALS];
uniform int st_bleed;
uniform int st_boundary;

// The material at texture position t: -1 outside the grid, where removed, or outside
// every material.
int st_materialAt(vec3 t)
{
  if (any(lessThan(t, vec3(0.0))) || any(greaterThan(t, vec3(1.0))) || !st_kept(t))
  {
    return -1;
  }
  vec2 at = st_materialCoordAt(t);
  return at.y < 0.0 ? -1 : int(floor(texture(st_materialTable, at).r + 0.5));
}

// Only bleeding and the boundary rescale need the material at each photon.
bool st_looksAtPhotons()
{
  return st_materialCount > 1 && (st_bleed != 0 || st_boundary != 0);
}

// Photon k of material m: its offset in grid units and its weight.
vec4 st_photon(int m, int k)
{
  vec4 photon = texelFetch(st_kernel, ivec2(k, m), 0);
  return vec4(st_worldToGrid * photon.xyz, photon.w);
}
