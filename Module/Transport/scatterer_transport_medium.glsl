//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 0a: what each fine texel holds that no light changes
// (all layers in one draw). It runs when the medium does (the volume, its transfer
// functions, clipping, cropping, the materials, the grid), not when a light moves:
// an orbit under the headlight or ParaView's light kit moves the lights every frame.
// - output 0 (FineScattering, rgb): the texel's scattering coefficient as the
//   multiple-scattering source takes it (scatterer_transport_source.glsl),
//     sigma_s(q) / cosh(tau_half(q)),   sigma_s = sigma_t albedo,
//   tau_half = OcclusionStrength sigma_t(q) h / 2 over half a fine texel of mean size
//   h, sigma_s and sigma_t the means over the texel's points (st_subsample: its centre,
//   or 2^3 points on a frame built coarser while the user drags): the source is
//   sigma_s(q) A(q), and the arriving light's texels hold their mean along each
//   light's line, A(q) cosh(tau_half) (scatterer_transport_sweep.glsl);
//   exact for a light along an axis (one across the texel's diagonal crosses up to
//   sqrt(3) h of it).
// - output 1 (FineGather, st_storedGather): which gather the texel takes
//   (scatterer_transport_gather.glsl): -1 outside every material; its material m when
//   no photon of m's templates lands in another material (the photons then need no
//   material look-up: no tint, no rescale); m + 8 (ST_MIXED) when one does.
// - output 2 (FineExtinction): the extinction along light paths (st_attenuationAt),
//   the mean over st_meanPoints^3 points spread evenly over the texel: the sweeps take
//   the far half of each step toward the light from it (st_stepDepth,
//   scatterer_transport_sweep_common.glsl). With st_meanPoints 0 (a texel of one voxel)
//   the sweeps take no mean: none is computed, and output 2 has no target.
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Materials
//VTK::Transport::StoredGather
in vec2 texCoord;
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)
uniform float st_fineSize; // a fine texel's mean size, world units
uniform int st_meanPoints; // output 2: points per axis (ExtinctionSampling::MeanPoints)

void main()
{
  vec3 j = vec3(floor(texCoord * st_gridDims.xy), st_layer);
  vec3 t = st_gridToTexture(j);
  vec4 medium = vec4(0.0); // rgb sigma_s, a sigma_t
  int points = st_subsamples * st_subsamples * st_subsamples;
  for (int k = 0; k < points; ++k)
  {
    vec4 m = st_mediumAt(st_gridToTexture(st_subsample(j, k)));
    medium += vec4(m.rgb * m.a, m.a);
  }
  medium /= float(points);
  // 1 / cosh(tau_half) without overflow.
  float e = exp(-0.5 * st_occlusionScale * medium.a * st_fineSize);
  float toCentre = 2.0 * e / (1.0 + e * e);
  int m = st_materialAt(t);
  float gather = -1.0;
  if (m >= 0)
  {
    bool mixed = false;
    if (st_looksAtPhotons())
    {
      for (int k = 0; k < st_kernelCount && !mixed; ++k)
      {
        int mp = st_materialAt(st_gridToTexture(j + st_photon(m, k).xyz));
        mixed = mp >= 0 && mp != m;
      }
    }
    gather = float(m) + (mixed ? float(ST_MIXED) : 0.0);
  }
  float extinction = 0.0;
  int n = st_meanPoints;
  for (int k = 0; k < n * n * n; ++k)
  {
    extinction += st_attenuationAt(st_gridToTexture(st_texelPoint(j, k, n)));
  }
  gl_FragData[0] = vec4(medium.rgb * toCentre, 1.0);
  gl_FragData[1] = vec4(st_storedGather(gather));
  gl_FragData[2] = vec4(n > 0 ? extinction / float(n * n * n) : 0.0);
}
