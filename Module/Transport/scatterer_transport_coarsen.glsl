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
// (albedo, sigma_t) is taken over its fine texels' points (st_mediumAt at
// st_subsamples^3 points of each: the centre, or 2^3 points on a frame built coarser
// while the user drags). Never one point sample of a block: see ScattererTransportGrid.cxx,
// CoarseGrid::Over.
// - sigma_t: the mean over all the points (a point without matter adds 0);
// - albedo: the mean over the points that hold matter (sigma_t > 0), over the block
//   grown by half a block on each side, the grown part at half weight (below). A point
//   without matter scatters nothing, so its colour (what the transfer function gives a
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
//   Why the grown block: the albedo decides how much of each colour the diffusion
//   absorbs, so a coarse texel's albedo is the colour of its multiple scattering. Over
//   the block alone it is a box sample of a field that changes within a block: where a
//   surface between two materials (the CT head's scalp over its skull) climbs through
//   the coarse layers, each texel holds another share of each, and the multiple
//   scattering's colour stepped from layer to layer (pink and ivory rings on the
//   crown). Overlapping the neighbours' blocks by half a block at half weight (a
//   tent-like prefilter) smooths the steps; the extinction stays the block's own, so
//   where light enters, is held and escapes does not move. It brought the CT head
//   closer to the Monte Carlo reference in both measures and took the skull phantom's
//   bands down; the margin at full weight, or a whole block wide, came out farther in
//   SSIM (docs/accuracy.md, "The coarse albedo's neighbourhood";
//   TransportVolume.MultipleScatteringColourFollowsTheMatterNotTheCoarseGrid).
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
// Points per fine texel and axis (CoarseGrid::Subsamples): 2 on a frame built coarser
// while the user drags, else 1, the texel's centre.
uniform int st_subsamples;

// The weight of a point in the albedo's margin against one of the block's own (above).
const float st_albedoMarginWeight = 0.5;

void main()
{
  ivec3 block = ivec3(st_blockSize + 0.5);
  vec3 c = vec3(floor(texCoord * st_coarseDims.xy), st_layer);
  vec3 b = vec3(block);
  vec3 fine = c * b + st_coarseToGrid;
  // The points lie on a lattice of st_subsamples per fine texel and axis, spread evenly
  // as st_texelPoint spreads them: point q at fine + (q + 0.5) / st_subsamples - 0.5, the
  // block's own for q in [0, own). The albedo's margin is half of that on each side (at
  // least one point).
  ivec3 own = block * st_subsamples;
  ivec3 margin = (own + 1) / 2;
  ivec3 wide = own + 2 * margin;
  vec3 albedo = vec3(0.0); // the weighted albedos of the points of matter
  float matter = 0.0;      // their weights
  float extinction = 0.0;  // sigma_t summed over the block's own points
  for (int k = 0; k < wide.x * wide.y * wide.z; ++k)
  {
    ivec3 q = ivec3(k % wide.x, (k / wide.x) % wide.y, k / (wide.x * wide.y)) - margin;
    // Outside the grid the medium is empty.
    vec4 m = st_mediumAt(
      st_gridToTexture(fine + (vec3(q) + 0.5) / float(st_subsamples) - vec3(0.5)));
    bool inBlock = all(greaterThanEqual(q, ivec3(0))) && all(lessThan(q, own));
    float weight = m.a > 0.0 ? (inBlock ? 1.0 : st_albedoMarginWeight) : 0.0;
    albedo += weight * m.rgb;
    matter += weight;
    extinction += inBlock ? m.a : 0.0;
  }
  vec4 medium = vec4(albedo / max(matter, 1.0e-6), extinction / float(own.x * own.y * own.z));
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
