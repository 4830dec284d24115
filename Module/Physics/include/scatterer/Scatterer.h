// Everything of the VTK-free scatterer-template core in one include.
#pragma once

#include <scatterer/GeneratorSettings.h>
#include <scatterer/Half.h>
#include <scatterer/Transport.h>
#include <scatterer/Material.h>
#include <scatterer/Pack.h>
#include <scatterer/Random.h>
#include <scatterer/Snell.h>
#include <scatterer/Template.h>
#include <scatterer/TemplateIO.h>
