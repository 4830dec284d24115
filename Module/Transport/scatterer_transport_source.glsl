//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 3a: the multiple-scattering source on the diffusion's
// coarse grid (its tiles that hold a medium, into its atlas), for the lights of this
// build. A coarse texel's
// source is the mean over its block of fine texels q (st_blockSize along each axis) of the light
// scattered once there,
//   S(q) = sigma_s(q) A(q)
// with A the light arriving unscattered (scatterer_transport_arriving.glsl), the texel's
// mean from the light entering it: st_fineScattering holds
// sigma_s(q) (1 - exp(-2x)) / (2x), x half the texel's optical depth (pass 0a,
// scatterer_transport_medium.glsl). Outside the grid the medium is empty.
//
// Alpha holds what the diffusion loses through the texel's free faces a unit fluence
// (scatterer_transport_diffuse.glsl, where the equation is): it depends on the coarse
// medium alone, so it is taken here once a build instead of at every Jacobi step, and
// the step reads it with the source in one fetch.
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Arriving
//VTK::Transport::Atlas
in vec2 texCoord;
uniform sampler3D st_fineScattering; // pass 0a: rgb = sigma_s (1 - exp(-2x)) / (2x)
flat in float st_layer;            // this layer (scatterer_transport_tiles_vs.glsl)
uniform vec3 st_coarseToGrid;      // coarse texel c covers fine positions c * st_blockSize + st_coarseToGrid + [0, st_blockSize)
uniform vec3 st_blockSize;         // fine texels a coarse texel spans along each axis
uniform sampler3D st_coarseMedium; // pass 0b: rgb albedo, a sigma_t
uniform vec3 st_h;                 // coarse texel size along each axis, world units

// Coarse texel c holds no medium (the light escapes there), or lies outside the grid.
bool st_empty(ivec3 c)
{
  return any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(st_coarseDims))) ||
    !st_holdsMedium(texelFetch(st_coarseMedium, c, 0));
}

// The escape of coarse texel c: sum over its faces toward no medium of
// max(0, 1 / (2 h_a) - D / h_a^2), D = 1 / (3 sigma_t); 0 where c holds no medium.
float st_escape(ivec3 c)
{
  if (st_empty(c))
  {
    return 0.0;
  }
  float D = 1.0 / (3.0 * texelFetch(st_coarseMedium, c, 0).a);
  float escape = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    for (int side = -1; side <= 1; side += 2)
    {
      ivec3 n = c;
      n[a] += side;
      escape += st_empty(n) ? max(0.0, 0.5 / st_h[a] - D / (st_h[a] * st_h[a])) : 0.0;
    }
  }
  return escape;
}

void main()
{
  ivec3 block = ivec3(st_blockSize + 0.5);
  ivec3 c = ivec3(ivec2(floor(texCoord * st_coarseDims.xy)), int(st_layer));
  ivec3 fine = c * block + ivec3(st_coarseToGrid);
  ivec3 dims = ivec3(st_gridDims);
  vec3 source = vec3(0.0);
  for (int k = 0; k < block.x * block.y * block.z; ++k)
  {
    ivec3 q = fine + ivec3(k % block.x, (k / block.x) % block.y, k / (block.x * block.y));
    if (all(greaterThanEqual(q, ivec3(0))) && all(lessThan(q, dims)))
    {
      source += texelFetch(st_fineScattering, q, 0).rgb * st_arrivingAtTexel(q);
    }
  }
  gl_FragData[0] = vec4(source / float(block.x * block.y * block.z), st_escape(c));
}
