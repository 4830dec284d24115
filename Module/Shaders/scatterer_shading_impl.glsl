    // Composite step with scatterer-template illumination (ScattererTemplate).
//ST::IF GROUPED
//ST::IF GROUP_START
    // @LIGHT_STRIDE@ samples share one read of the light transport volume
    // (scatterer::illumination::lightReadStride): this one reads the light where the
    // next group starts, and the samples between take the light between the two reads
    // geometrically, L_k = L_0 (L_n / L_0)^(k/n): the optical depth interpolated
    // linearly, exact where the light falls off as Beer-Lambert's exp(-tau) along the
    // ray (docs/model.md, "Fewer light reads"). The reads are compressed
    // (st_shownLight) as they are taken, once a group rather than per sample.
    vec3 st_lightStart = st_lightEnd;
    st_lightEnd =
      st_shownLight(st_transportRead(g_dataPos + float(@LIGHT_STRIDE@) * g_dirStep));
    vec3 st_lightStep =
      st_strideRoot(max(st_lightEnd, st_lightFloor) / max(st_lightStart, st_lightFloor));
    vec3 st_light = max(st_lightStart, st_lightFloor);
      {
//ST::ELSE
      {
      // Sample @K@ of the group: the ray caster's own step to the next sample, and its
      // per-sample code, as its loop runs them between two samples.
      g_dataPos += g_dirStep;
      //VTK::Terminate::Impl
      //VTK::Base::Impl
      //VTK::Cropping::Impl
      //VTK::BinaryMask::Impl
      //VTK::CompositeMask::Impl
      //VTK::PreComputeGradients::Impl
      st_light *= st_lightStep;
//ST::ENDIF
//ST::ENDIF
//ST::IF PERSAMPLE
    st_step += 1;
//ST::ENDIF
    if (!g_skip)
      {
      vec4 scalar = texture3D(in_volume[0], g_dataPos);
//ST::IF INDEPENDENT
      // Independent components, composited as VTK 9.1 does (vtkVolumeShaderComposer's
      // shading): each component's own opacity and colour (with VTK's gradient shading
      // per component when Shade is on), mixed by the component weights into one
      // premultiplied colour with opacity sum(alpha_c^2) / sum(w_c alpha_c). The mix is
      // then lit below, as one sample.
      scalar = scalar * in_volume_scale[0] + in_volume_bias[0];
      vec4 st_parts[4];
      float st_total = 0.0;
      for (int i = 0; i < in_noOfComponents; ++i)
        {
        st_parts[i][3] = computeOpacity(scalar, i);
        st_parts[i] = computeColor(scalar, st_parts[i][3], i);
        st_total += st_parts[i][3] * in_componentWeight[i];
        }
      g_srcColor = vec4(0.0);
      for (int i = 0; i < in_noOfComponents && st_total > 0.0; ++i)
        {
        if (in_componentWeight[i] <= 0.0)
          {
          continue;
          }
        g_srcColor.rgb += st_parts[i].rgb * st_parts[i].a * in_componentWeight[i];
        g_srcColor.a += st_parts[i].a * st_parts[i].a / st_total;
        }
      if (g_srcColor.a > 0.0)
        {
//ST::ELSE
//ST::IF DEPENDENT
      // Dependent components (luminance + alpha, RGBA): VTK's computeOpacity and
      // computeColor read the whole vector.
      scalar = scalar * in_volume_scale[0] + in_volume_bias[0];
//ST::ELSE
      scalar.r = scalar.r * in_volume_scale[0].r + in_volume_bias[0].r;
      scalar = vec4(scalar.r);
//ST::ENDIF
//ST::IF LABELMASK
      // VTK 9.1's label-map mask (vtkVolumeShaderComposer, CompositeMaskImplementation):
      // label 0, or a blend factor of 0, takes the volume's own transfer functions; any
      // other label its row of in_labelMapTransfer (colour and opacity over the scalar),
      // mixed by in_maskBlendFactor. That colour is then lit like any other.
      float st_opacity = computeOpacity(scalar);
      g_srcColor = computeColor(scalar, st_opacity);
      if (in_maskBlendFactor > 0.0 && in_labelMapNumLabels > 0)
        {
        float st_labelRow = texture3D(in_mask, g_dataPos).r * in_mask_scale + in_mask_bias;
        st_labelRow = floor(st_labelRow * float(in_labelMapNumLabels)) / float(in_labelMapNumLabels);
        if (st_labelRow != 0.0)
          {
          vec4 st_labelColor = texture2D(in_labelMapTransfer, vec2(scalar.r, st_labelRow));
          g_srcColor = in_maskBlendFactor < 1.0
            ? (1.0 - in_maskBlendFactor) * g_srcColor + in_maskBlendFactor * st_labelColor
            : st_labelColor;
          }
        }
      if (g_srcColor.a > 0.0)
        {
//ST::ELSE
      g_srcColor = vec4(0.0);
      g_srcColor.a = computeOpacity(scalar);
      if (g_srcColor.a > 0.0)
        {
        g_srcColor = computeColor(scalar, g_srcColor.a);
//ST::ENDIF
//ST::ENDIF
//ST::IF PERSAMPLE
        int st_m = st_material(scalar.r);
//ST::ELSE
        // Every visible sample reads the transport volume.
        const int st_m = 0;
//ST::ENDIF
//ST::IF TRANSPORT
        // The light transport volume: the light this point receives, summed over
        // the lights (global shadows, template in-scattering, multiple scattering,
        // VTK's ambient term occluded like the light), between the group's reads or
        // read here.
//ST::IF GROUPED
        st_F = st_light;
//ST::ELSE
        st_F = st_shownLight(st_transportRead(g_dataPos));
//ST::ENDIF
//ST::ENDIF
//ST::IF PERSAMPLE
        // A loop of 0 or 1 iterations rather than an if: a GPU skips a loop no
        // lane of a SIMD group enters.
        int st_evaluate = (st_m >= 0 &&
          (st_m != st_cachedMaterial || st_step % st_interval == 0)) ? 1 : 0;
        for (int st_once = 0; st_once < st_evaluate; ++st_once)
          {
          st_illuminate(g_dataPos, st_m, 1.0 - g_fragColor.a, st_F, st_B);
          st_cachedMaterial = st_m;
          }
//ST::ENDIF
        if (st_m >= 0)
          {
//ST::IF INDEPENDENT
          // The mix is premultiplied (and may exceed its opacity where components
          // overlap, as in VTK): the light scales it as it would scale each component.
//ST::IF PHONG
          g_srcColor.rgb = max(g_srcColor.rgb * st_F * st_unlitNorm, 0.0);
//ST::ELSE
          g_srcColor.rgb = max(g_srcColor.rgb * st_F, 0.0);
//ST::ENDIF
//ST::ELSE
//ST::IF PHONG
          // VTK's gradient shading stays; the template visibility darkens it.
          g_srcColor.rgb = clamp((g_srcColor.rgb * st_F + st_B) * st_unlitNorm, 0.0, 1.0);
//ST::ELSE
//ST::IF SURFACE
          // The ray's first dense samples: their light is taken again after the ray loop
          // (st_surfaceChange); kept here, where on the ray and what of it was left, in
          // the count's slot. Without branch or indexed store: llvmpipe runs both for
          // every sample.
          bool st_kept = g_srcColor.a > st_surfaceAlpha && st_surfaceCount < ST_SURFACE_SAMPLES;
          vec4 st_slot = vec4(equal(ivec4(0, 1, 2, 3), ivec4(st_kept ? st_surfaceCount : -1)));
          st_surfaceAt = mix(st_surfaceAt,
            vec4(dot(g_dataPos - st_rayStart, g_dirStep) * st_perStep), st_slot);
          st_surfaceLeft = mix(st_surfaceLeft, vec4(1.0 - g_fragColor.a), st_slot);
          st_surfaceCount += st_kept ? 1 : 0;
//ST::ENDIF
          g_srcColor.rgb = clamp(g_srcColor.rgb * st_F + st_B, 0.0, 1.0);
//ST::ENDIF
//ST::ENDIF
          }
//ST::IF INDEPENDENT
//ST::ELSE
        g_srcColor.rgb *= g_srcColor.a;
//ST::ENDIF
        g_fragColor = (1.0f - g_fragColor.a) * g_srcColor + g_fragColor;
        }
      }
//ST::IF GROUPED
//ST::IF GROUP_END
//ST::ELSE
      //VTK::RenderToImage::Impl
      //VTK::DepthPass::Impl
//ST::ENDIF
      }
//ST::ENDIF
