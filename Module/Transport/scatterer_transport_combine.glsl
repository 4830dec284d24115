//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 4: added to the light each fine texel receives (by
// blending), both linearly interpolated from the coarse grid:
// - the multiply scattered light: the diffusion's fluence times MultipleScattering;
// - VTK's ambient term (ka x the lights' ambient colours) times its occlusion
//   (pass 0b, scatterer_transport_coarsen.glsl).
//============================================================================
in vec2 texCoord;
uniform sampler3D st_fluence;      // coarse grid, rgb (unused when st_strength is 0)
uniform sampler3D st_occlusion;    // coarse grid: the ambient light's transmittance (pass 0b)
uniform vec3 st_ambient;
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)
uniform vec3 st_gridDims;
uniform vec3 st_coarseDims;
uniform vec3 st_coarseToGrid;
uniform float st_block;
uniform float st_strength;

void main()
{
  vec3 j = vec3(floor(texCoord * st_gridDims.xy), st_layer);
  // Coarse texel c's centre is at fine position c * b + st_coarseToGrid + (b - 1) / 2.
  vec3 c = (j - st_coarseToGrid - vec3(0.5 * (st_block - 1.0))) / st_block;
  vec3 coarse = (c + vec3(0.5)) / st_coarseDims;
  vec3 scattered = st_strength > 0.0 ? st_strength * texture(st_fluence, coarse).rgb : vec3(0.0);
  gl_FragData[0] = vec4(scattered + st_ambient * texture(st_occlusion, coarse).r, 1.0);
}
