//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 1: transmittance sweep (one slice per draw).
//
// Light propagation slice by slice along the light's dominant grid axis
// (Behrens & Ratering 1998; Ropinski et al. 2010): a texel of slice k takes the
// transmittance of slice k -/+ 1 where the line toward the light crosses it, and
// multiplies it by Beer-Lambert over the step between the two:
//   T(p) = T(q) * exp(-integral_q^p sigma_t ds)          (Beer-Lambert)
// so T holds the fraction of the light's energy that reaches p through the whole
// volume, in O(N) per light. Directional lights: one direction for all texels.
// Positional lights: the direction toward the light per texel, and slices are
// swept away from the light's own slice on both sides (the radial variant).
//============================================================================
//VTK::Transport::Common
in vec2 texCoord;
uniform sampler2D st_previous;     // the slice swept before this one
uniform int st_hasPrevious;        // 0: first slice of a sweep, T = 1
uniform float st_slice;            // this slice's index along the sweep axis
uniform vec3 st_sweepDims;         // (rows, columns, slices) of the sweep texture
uniform mat3 st_worldToGrid;       // world vector -> grid-index vector
uniform mat3 st_gridToWorld;       // grid-index vector -> world vector
uniform vec3 st_lightToward;       // directional: unit vector toward the light (world)
uniform vec3 st_lightPosition;     // positional: world position
uniform int st_lightPositional;
uniform int st_substeps;           // extinction samples per step (volume voxels per texel)

void main()
{
  vec3 js = vec3(floor(texCoord * st_sweepDims.xy), st_slice);
  vec3 j = transpose(st_toSweep) * js;
  float T = 1.0;
  if (st_hasPrevious != 0)
  {
    vec3 toward = st_lightToward;
    if (st_lightPositional != 0)
    {
      vec4 p = st_texToWorld * vec4(st_gridToTexture(j), 1.0);
      toward = st_lightPosition - p.xyz / p.w;
    }
    vec3 ds = st_toSweep * (st_worldToGrid * toward);
    // One slice toward the light; a light nearly in this slice's plane would
    // shift sideways without bound: at most 4 texels per step.
    float along = max(abs(ds.z), length(ds.xy) / 4.0);
    vec3 stepSweep = ds / max(along, 1.0e-20);
    stepSweep.z = sign(ds.z);
    vec3 qs = js + stepSweep;
    vec3 stepGrid = transpose(st_toSweep) * stepSweep;
    float len = length(st_gridToWorld * stepGrid);
    float tau = 0.0;
    for (int i = 0; i < st_substeps; ++i)
    {
      vec3 g = j + stepGrid * ((float(i) + 0.5) / float(st_substeps));
      tau += st_attenuationAt(st_gridToTexture(g));
    }
    tau *= len / float(st_substeps);
    // Outside the grid the light has crossed no matter: the border reads 1.
    float Tq = texture(st_previous, (qs.xy + vec2(0.5)) / st_sweepDims.xy).r;
    T = Tq * exp(-tau);
  }
  gl_FragData[0] = vec4(T);
  gl_FragData[1] = vec4(T);
}
