//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 3a: the medium and the multiple-scattering source
// on the diffusion's coarse grid (one layer per draw). A coarse texel covers a block
// of st_block^3 fine texels (st_block: 4 or 2, so that a coarse texel spans about
// 4 volume voxels, or 2 fine texels at TransportScale 3 and above): its medium
// (albedo, sigma_t) is the mean of theirs (st_mediumAt at each), its source the mean
// of theirs, the light scattered once at each fine texel q:
//   S(q) = sigma_t(q) albedo(q) A(q)
// with A the light arriving unscattered (scatterer_transport_arriving.glsl). Never one
// point sample: see ScattererTransportGrid.cxx, CoarseGrid::Over. The arriving light's
// texels hold their mean along each light's line, A(q) cosh(tau_half)
// (scatterer_transport_sweep.glsl); the source takes the value at q back from it, with
// tau_half = OcclusionStrength sigma_t(q) h / 2 (the sweep's attenuation) for a fine
// texel of mean size h (exact for a light along an axis; a light across the texel's
// diagonal crosses up to sqrt(3) h of it).
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
//VTK::Transport::Arriving
in vec2 texCoord;
uniform float st_layer;
uniform vec3 st_coarseDims;
uniform vec3 st_coarseToGrid;      // coarse texel c covers fine positions c * st_block + st_coarseToGrid + [0, st_block)
uniform int st_block;
uniform vec3 st_h;                 // coarse texel size along each axis, world units
uniform int st_aoSteps;

void main()
{
  vec3 c = vec3(floor(texCoord * st_coarseDims.xy), st_layer);
  float b = float(st_block);
  vec3 fine = c * b + st_coarseToGrid;
  vec4 medium = vec4(0.0);
  vec3 source = vec3(0.0);
  ivec3 last = ivec3(st_gridDims) - ivec3(1);
  float fineSize = (st_h.x + st_h.y + st_h.z) / (3.0 * b); // a fine texel's mean size
  for (int k = 0; k < st_block * st_block * st_block; ++k)
  {
    vec3 o = vec3(float(k % st_block), float((k / st_block) % st_block), float(k / (st_block * st_block)));
    vec4 m = st_mediumAt(st_gridToTexture(fine + o));
    medium += m;
    // Outside the grid the medium is empty: the clamped texel adds nothing.
    // A(q) from its texel's mean (the sweep's T_texel = T(q) cosh(tau_half)), with
    // tau_half over half a fine texel of q's medium; 1 / cosh without overflow.
    float e = exp(-0.5 * st_occlusionScale * m.a * fineSize);
    float toCentre = 2.0 * e / (1.0 + e * e);
    source += m.a * m.rgb * st_arrivingAtTexel(clamp(ivec3(fine + o), ivec3(0), last)) * toCentre;
  }
  medium /= b * b * b;
  source /= b * b * b;
  vec3 centre = fine + vec3(0.5 * (b - 1.0));
  float open = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    float best = 0.0;
    for (int side = 0; side < 2; ++side)
    {
      vec3 axis = vec3(0.0);
      axis[a] = side == 0 ? b : -b; // one coarse voxel in fine grid units
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
  gl_FragData[1] = vec4(source, open / 3.0);
}
