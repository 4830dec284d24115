//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 3a: the medium and the multiple-scattering source
// on the diffusion's coarse grid (one layer per draw). A coarse texel covers 2x2x2
// fine texels: its medium (albedo, sigma_t) is the mean of theirs (st_mediumAt at
// the eight), its source the mean of theirs (one linear fetch at the block centre).
//
// Its alpha also carries the ambient occlusion of the block centre p: VTK's ambient
// light comes from every direction, so it is occluded by the medium around p.
// Along each axis, the more open of its two directions counts (a surface is open
// on one side, like the hemisphere above it), each marched over st_aoSteps coarse
// voxels from the next one on (the block's own medium is what the ambient light
// lights, not what occludes it; so a plate thinner than a block is open on its
// free side):
//   AO(p) = 1/3 sum_a max_(d = +-e_a) exp(-h_a sum_(k=1..n) sigma_t(p + k h_a d))
// so free space gets 1, a flat surface at least 1/3 and a point deep inside 0.
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
  for (int a = 0; a < 3; ++a)
  {
    float best = 0.0;
    for (int side = 0; side < 2; ++side)
    {
      vec3 axis = vec3(0.0);
      axis[a] = side == 0 ? 2.0 : -2.0; // one coarse voxel in fine grid units
      float tau = 0.0;
      for (int k = 0; k < st_aoSteps; ++k)
      {
        tau += st_attenuationAt(st_gridToTexture(centre + float(k + 1) * axis));
      }
      best = max(best, exp(-tau * st_h[a]));
    }
    open += best;
  }
  gl_FragData[0] = medium / 8.0;
  gl_FragData[1] = vec4(texture(st_source, (fine + vec3(1.0)) / st_gridDims).rgb, open / 3.0);
}
