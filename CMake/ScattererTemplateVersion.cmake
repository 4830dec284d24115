# The ScattererTemplate version: the one place it is written. The top-level project and
# the ParaView plugin's project take it (project(... VERSION)); from there it reaches
# ScattererTemplate_VERSION (find_package), vtkScattererTemplateVersion,
# scatterertemplate.__version__ and every program's --version.
set(SCATTERER_TEMPLATE_VERSION 0.1.0)
