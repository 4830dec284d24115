//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 4: the multiply scattered light (the diffusion's
// fluence, linearly interpolated from the coarse grid, times MultipleScattering)
// added to the light each fine texel receives (by blending).
//============================================================================
in vec2 texCoord;
uniform sampler3D st_fluence;      // coarse grid, rgb
uniform float st_layer;
uniform vec3 st_gridDims;
uniform vec3 st_coarseDims;
uniform vec3 st_coarseToGrid;
uniform float st_strength;

void main()
{
  vec3 j = vec3(floor(texCoord * st_gridDims.xy), st_layer);
  // Coarse texel c's centre is at fine position c * 2 + st_coarseToGrid + 0.5.
  vec3 c = (j - st_coarseToGrid - vec3(0.5)) / 2.0;
  gl_FragData[0] = vec4(st_strength * texture(st_fluence, (c + vec3(0.5)) / st_coarseDims).rgb, 1.0);
}
