//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 3a: the multiple-scattering source on the diffusion's
// coarse grid (its tiles that hold a medium, into its atlas), for the lights of this
// build. A coarse texel's
// source is the mean over its block of st_block^3 fine texels q of the light
// scattered once there,
//   S(q) = sigma_s(q) A(q)
// with A the light arriving unscattered (scatterer_transport_arriving.glsl), the texel's
// mean from the light entering it: st_fineScattering holds
// sigma_s(q) (1 - exp(-2x)) / (2x), x half the texel's optical depth (pass 0a,
// scatterer_transport_medium.glsl). Outside the grid the medium is empty.
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Arriving
in vec2 texCoord;
uniform sampler3D st_fineScattering; // pass 0a: rgb = sigma_s (1 - exp(-2x)) / (2x)
flat in float st_layer;            // this layer (scatterer_transport_tiles_vs.glsl)
uniform vec3 st_coarseDims;
uniform vec3 st_coarseToGrid;      // coarse texel c covers fine positions c * st_block + st_coarseToGrid + [0, st_block)
uniform int st_block;

void main()
{
  ivec3 fine = ivec3(vec3(floor(texCoord * st_coarseDims.xy), st_layer) * float(st_block) + st_coarseToGrid);
  ivec3 dims = ivec3(st_gridDims);
  vec3 source = vec3(0.0);
  for (int k = 0; k < st_block * st_block * st_block; ++k)
  {
    ivec3 q = fine + ivec3(k % st_block, (k / st_block) % st_block, k / (st_block * st_block));
    if (all(greaterThanEqual(q, ivec3(0))) && all(lessThan(q, dims)))
    {
      source += texelFetch(st_fineScattering, q, 0).rgb * st_arrivingAtTexel(q);
    }
  }
  float b = float(st_block);
  gl_FragData[0] = vec4(source / (b * b * b), 1.0);
}
