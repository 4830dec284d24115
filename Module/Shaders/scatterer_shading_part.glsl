      // Input @PART@ of a vtkMultiVolume (ScattererTemplate), composited as VTK 9.1's
      // ray caster composites it (vtkVolumeShaderComposer, multi-volume shading): its
      // own texture position, scale and bias, transfer functions and gradient shading,
      // blended front to back after the inputs before it. The light it receives is the
      // one transport volume's, which carries the light through all the inputs.
      texPos = (in_cellToPoint[@MATRIX@] * in_inverseTextureDatasetMatrix[@MATRIX@] *
        in_inverseVolumeMatrix[@MATRIX@] * in_volumeMatrix[0] * in_textureDatasetMatrix[0] *
        vec4(g_dataPos.xyz, 1.0)).xyz;
      if (all(lessThanEqual(texPos, vec3(1.0))) && all(greaterThanEqual(texPos, vec3(0.0))))
        {
        vec4 scalar = texture3D(in_volume[@PART@], texPos);
        scalar = scalar * in_volume_scale[@PART@] + in_volume_bias[@PART@];
        scalar = vec4(scalar.r);
        g_srcColor = vec4(0.0);
        g_srcColor.a = computeOpacity(scalar, in_opacityTransferFunc_@PART@[0]);
        if (g_srcColor.a > 0.0)
          {
          g_srcColor = computeColor(texPos, scalar, g_srcColor.a, in_colorTransferFunc_@PART@[0],
            in_volume[@PART@], @PART@);
          st_F = st_shownLight(st_transportRead(g_dataPos));
//ST::IF PHONG
          g_srcColor.rgb = clamp(g_srcColor.rgb * st_F * st_unlitNorm, 0.0, 1.0);
//ST::ELSE
          g_srcColor.rgb = clamp(g_srcColor.rgb * st_F, 0.0, 1.0);
//ST::ENDIF
          g_srcColor.rgb *= g_srcColor.a;
          g_fragColor = (1.0f - g_fragColor.a) * g_srcColor + g_fragColor;
          }
        }
