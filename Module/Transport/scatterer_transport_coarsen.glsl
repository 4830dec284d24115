//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 0b: the medium on the diffusion's coarse grid and the
// ambient occlusion of each coarse texel (all layers in one draw). Like pass 0a it runs
// when the medium changes, not when a light moves. A coarse texel covers a block of
// st_blockSize fine texels along each axis (4 or 2, so that a coarse texel spans about 4
// volume voxels, or 2 fine texels at TransportScale 3 and above; 1 on a frame built
// coarser while the user drags, whose coarse texels stay a still frame's; fewer along an
// axis of long voxels: scatterer::illumination::diffusionBlocksFor): its medium
// (albedo, sigma_t) is taken over its fine texels' points (st_mediumAt at each
// st_subsample: the centre, or 2^3 points on a frame built coarser while the user
// drags). Never one point sample of a block: see ScattererTransportGrid.cxx,
// CoarseGrid::Over.
// - sigma_t: the mean over all the points (a point without matter adds 0);
// - albedo: the mean over the points that hold matter (sigma_t > 0). A point without
//   matter scatters nothing, so its colour (what the transfer function gives a
//   transparent scalar, air or a range of opacity 0, or 0 where clipping or cropping
//   removed it) must not colour the light. Taken over all the points (until
//   2026-12-07), a black colour at the CT head's transparent scalars (air and 0-150 HU,
//   which no ray shows) darkened its lit picture by 7 % (85 levels at most), and a blue
//   one tinted it (TransportVolume.ColourOfTransparentScalarsDoesNotReachTheLight).
//   The points of matter count alike, not by their extinction: weighted by it (the
//   mixture's albedo, sigma_s / sigma_t summed over the points), bone outweighs the skin
//   over it in every coarse texel they share, the multiple scattering of the CT head's
//   crown came out whiter than the Monte Carlo reference's and the defaults moved away
//   from it (docs/accuracy.md, "Transparent colours").
//
// The second target holds the ambient occlusion of the block centre p: VTK's ambient
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
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)
uniform vec3 st_coarseDims;
uniform vec3 st_coarseToGrid;      // coarse texel c covers fine positions c * st_blockSize + st_coarseToGrid + [0, st_blockSize)
uniform vec3 st_blockSize;         // fine texels a coarse texel spans along each axis
uniform vec3 st_h;                 // coarse texel size along each axis, world units
uniform int st_aoSteps;

void main()
{
  ivec3 block = ivec3(st_blockSize + 0.5);
  vec3 c = vec3(floor(texCoord * st_coarseDims.xy), st_layer);
  vec3 b = vec3(block);
  vec3 fine = c * b + st_coarseToGrid;
  vec4 medium = vec4(0.0); // rgb the albedos of the points of matter, a all sigma_t
  float matter = 0.0;      // the points of matter
  int points = st_subsamples * st_subsamples * st_subsamples;
  for (int k = 0; k < block.x * block.y * block.z; ++k)
  {
    vec3 o = vec3(float(k % block.x), float((k / block.x) % block.y), float(k / (block.x * block.y)));
    for (int p = 0; p < points; ++p)
    {
      // Outside the grid the medium is empty.
      vec4 m = st_mediumAt(st_gridToTexture(st_subsample(fine + o, p)));
      float holds = m.a > 0.0 ? 1.0 : 0.0;
      medium += vec4(m.rgb * holds, m.a);
      matter += holds;
    }
  }
  medium.rgb /= max(matter, 1.0);
  medium.a /= b.x * b.y * b.z * float(points);
  vec3 centre = fine + vec3(0.5 * (b - 1.0));
  float open = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    float best = 0.0;
    for (int side = 0; side < 2; ++side)
    {
      vec3 axis = vec3(0.0);
      axis[a] = side == 0 ? b[a] : -b[a]; // one coarse voxel in fine grid units
      float tau = 0.0;
      for (int k = 0; k < st_aoSteps; ++k)
      {
        tau += st_attenuationAt(st_gridToTexture(centre + float(k + 1) * axis));
      }
      best = max(best, exp(-tau * st_h[a]));
    }
    open += best;
  }
  gl_FragData[0] = medium;
  gl_FragData[1] = vec4(open / 3.0);
}
