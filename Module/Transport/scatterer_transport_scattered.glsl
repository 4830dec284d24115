//============================================================================
// Light transport volume, pass 4, in the gather's draw (scatterer_transport_gather.glsl
// adds it to the light it writes): what a fine texel receives besides the light
// scattered once, both linearly interpolated from the diffusion's coarse grid:
// - the multiply scattered light: the diffusion's fluence times MultipleScattering;
// - VTK's ambient term (ka x the lights' ambient colours) times its occlusion
//   (pass 0b, scatterer_transport_coarsen.glsl).
// It needs nothing from the gather, so the diffusion runs before it and the gather
// writes the whole light at once: one pass over the fine grid fewer than a pass of its
// own adding to it by blending.
//============================================================================
//VTK::Transport::Atlas
// The coarse grid's atlas: rgb the fluence (unused when st_strength is 0), and the
// ambient light's transmittance on the coarse grid (pass 0b,
// scatterer_transport_coarsen.glsl).
uniform sampler2D st_fluence;
uniform sampler3D st_occlusion;
uniform vec3 st_ambient;
uniform vec3 st_coarseToGrid;
uniform vec3 st_blockSize; // fine texels a coarse texel spans along each axis
uniform float st_strength;

// The multiply scattered and the ambient light at grid position j.
vec3 st_scatteredAndAmbient(vec3 j)
{
  // Coarse texel c's centre is at fine position c * b + st_coarseToGrid + (b - 1) / 2.
  vec3 c = (j - st_coarseToGrid - 0.5 * (st_blockSize - 1.0)) / st_blockSize;
  vec3 coarse = (c + vec3(0.5)) / st_coarseDims;
  // Each read only where its term counts (uniforms: the same branch for every texel; a
  // vtkLight's ambient colour is black unless set).
  vec3 scattered =
    st_strength > 0.0 ? st_strength * st_atlasLinear(st_fluence, coarse).rgb : vec3(0.0);
  bool lit = any(greaterThan(st_ambient, vec3(0.0)));
  vec3 ambient = lit ? st_ambient * texture(st_occlusion, coarse).r : vec3(0.0);
  return scattered + ambient;
}
