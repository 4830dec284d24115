//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 3a: the medium and the multiple-scattering source
// on the diffusion's coarse grid (one layer per draw). A coarse texel covers 2x2x2
// fine texels: its medium (albedo, sigma_t) is the mean of theirs (st_mediumAt at
// the eight), its source the mean of theirs (one linear fetch at the block centre).
//
// Its alpha also carries the ambient occlusion of the block centre p: VTK's ambient
// light comes from every direction, so it is occluded by the medium around p,
// averaged over the six axis directions, each marched over st_aoSteps coarse voxels:
//   AO(p) = 1/6 sum_d exp(-h_d sum_k sigma_t(p + (k + 1/2) h_d d))      (Beer-Lambert)
//============================================================================
//VTK::Transport::Common
in vec2 texCoord;
uniform sampler3D st_source;       // fine grid: rgb = the light scattered once
uniform float st_layer;
uniform vec3 st_coarseDims;
uniform vec3 st_coarseToGrid;      // coarse texel c covers fine positions c * 2 + st_coarseToGrid, + 1
uniform vec3 st_h;                 // coarse texel size along each axis, world units
uniform int st_aoSteps;

void main()
{
  vec3 c = vec3(floor(texCoord * st_coarseDims.xy), st_layer);
  vec3 fine = c * 2.0 + st_coarseToGrid;
  vec4 medium = vec4(0.0);
  for (int k = 0; k < 8; ++k)
  {
    vec3 o = vec3(float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1));
    medium += st_mediumAt(st_gridToTexture(fine + o));
  }
  vec3 centre = fine + vec3(0.5);
  float open = 0.0;
  for (int d = 0; d < 6; ++d)
  {
    vec3 axis = vec3(0.0);
    axis[d / 2] = (d % 2 == 0) ? 2.0 : -2.0; // one coarse voxel in fine grid units
    float tau = 0.0;
    for (int k = 0; k < st_aoSteps; ++k)
    {
      tau += st_attenuationAt(st_gridToTexture(centre + (float(k) + 0.5) * axis));
    }
    open += exp(-tau * st_h[d / 2]);
  }
  gl_FragData[0] = medium / 8.0;
  gl_FragData[1] = vec4(texture(st_source, (fine + vec3(1.0)) / st_gridDims).rgb, open / 6.0);
}
