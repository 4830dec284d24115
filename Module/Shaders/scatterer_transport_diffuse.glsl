//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 3: multiple scattering by diffusion (one layer
// per draw, st_iterations Jacobi sweeps on a grid twice as coarse; after vpt,
// Zbontar & Lesar, which carries multiple scattering by diffusion).
//
// The diffusion approximation of the light scattered more than once, per colour
// channel (Ishimaru; Jensen et al. 2001, Eq. 4):
//   -div(D grad phi) + sigma_a phi = S,   D = 1 / (3 sigma_t),  sigma_a = sigma_t (1 - albedo)
// S (from the gather) is the light scattered once; phi the fluence it becomes.
// Discretised on the coarse grid with spacing h_a along axis a and solved by Jacobi
// iteration (D taken at the texel):
//   phi(x) = (S(x) + D sum_a (phi(x + e_a) + phi(x - e_a)) / h_a^2)
//            / (2 D sum_a 1 / h_a^2 + sigma_a)
// Where there is no medium the light escapes (phi = 0), as it does past the grid.
// The medium of a coarse texel (albedo, sigma_t) is the mean of its eight fine
// texels' (st_mediumAt); the source is read from the fine grid at the texel's centre,
// where linear filtering averages the eight.
//============================================================================
//VTK::Transport::Common
in vec2 texCoord;
uniform sampler3D st_source;       // fine grid: rgb = the light scattered once
uniform sampler3D st_previous;     // coarse grid: phi of the last iteration (rgb)
uniform int st_first;              // 1: no previous iteration (phi = 0)
uniform float st_layer;
uniform vec3 st_coarseDims;
uniform vec3 st_coarseToGrid;      // coarse texel c covers fine positions c * 2 + st_coarseToGrid
uniform vec3 st_h;                 // coarse texel size along each axis, world units

vec3 st_phi(vec3 c)
{
  if (st_first != 0 || any(lessThan(c, vec3(0.0))) || any(greaterThanEqual(c, st_coarseDims)))
  {
    return vec3(0.0);
  }
  return texelFetch(st_previous, ivec3(c), 0).rgb;
}

void main()
{
  vec3 c = vec3(floor(texCoord * st_coarseDims.xy), st_layer);
  vec3 fine = c * 2.0 + st_coarseToGrid; // the first of the eight fine texels
  vec4 medium = vec4(0.0);
  for (int k = 0; k < 8; ++k)
  {
    vec3 o = vec3(float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1));
    medium += st_mediumAt(st_gridToTexture(fine + o));
  }
  medium /= 8.0;
  if (medium.a <= 1.0e-6)
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  vec3 S = texture(st_source, (fine + vec3(1.0)) / st_gridDims).rgb;
  float D = 1.0 / (3.0 * medium.a);
  vec3 inv2 = 1.0 / (st_h * st_h);
  vec3 neighbours = vec3(0.0);
  for (int a = 0; a < 3; ++a)
  {
    vec3 e = vec3(0.0);
    e[a] = 1.0;
    neighbours += (st_phi(c + e) + st_phi(c - e)) * inv2[a];
  }
  vec3 sigmaA = medium.a * (vec3(1.0) - medium.rgb);
  vec3 phi = (S + D * neighbours) / (2.0 * D * (inv2.x + inv2.y + inv2.z) + sigmaA);
  gl_FragData[0] = vec4(phi, 1.0);
}
