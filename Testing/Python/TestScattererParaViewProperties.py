"""The ParaView plugin's server-manager XML against the mapper it drives: every
Scatterer* property forwards to a mapper setter, and its default and range are the
mapper's (so ParaView users get the defaults and clamping the C++ API documents).
Runs in the VTK 9.1 build: the XML is read as text, the mapper through its Python
wrapping."""
import os
import sys
import xml.etree.ElementTree as ET

from scatterertemplate import vtkScattererTemplateVolumeMapper

XML = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "ParaView", "Plugin",
                   "ScattererVolumeRepresentation.xml")
# Representation-only settings (no mapper counterpart).
NOT_MAPPER = {"SetGhostLayers", "SetLightExchangeEnabled"}

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


root = ET.parse(XML).getroot()
proxy = root.find("./ProxyGroup/RepresentationProxy[@name='ScattererVolumeRepresentation']")
check(proxy is not None, "ScattererVolumeRepresentation is defined")
mapper = vtkScattererTemplateVolumeMapper()
settings = 0
for prop in proxy if proxy is not None else []:
    command = prop.get("command", "")
    if not prop.get("name", "").startswith("Scatterer") or prop.get("information_only") == "1":
        continue
    if command in NOT_MAPPER:
        continue
    settings += 1
    name = command[len("Set"):]
    getter = getattr(mapper, "Get" + name, None)
    check(getter is not None, "%s: the mapper has Get%s" % (prop.get("name"), name))
    if getter is None:
        continue
    default = float(prop.get("default_values"))
    check(abs(float(getter()) - default) <= 1e-12 * max(1.0, abs(default)),
          "%s: XML default %s, mapper default %s" % (prop.get("name"), default, getter()))
    rng = prop.find("IntRangeDomain")
    if rng is None:
        rng = prop.find("DoubleRangeDomain")
    if rng is not None:
        low = getattr(mapper, "Get%sMinValue" % name)()
        check(float(rng.get("min")) == float(low),
              "%s: XML min %s, mapper min %s" % (prop.get("name"), rng.get("min"), low))
        if rng.get("max") is not None:
            high = getattr(mapper, "Get%sMaxValue" % name)()
            check(float(rng.get("max")) == float(high),
                  "%s: XML max %s, mapper max %s" % (prop.get("name"), rng.get("max"), high))
    enum = prop.find("EnumerationDomain")
    if enum is not None:
        values = sorted(int(e.get("value")) for e in enum.findall("Entry"))
        low, high = getattr(mapper, "Get%sMinValue" % name)(), getattr(mapper, "Get%sMaxValue" % name)()
        check(values == list(range(low, high + 1)),
              "%s: XML entries %s, mapper range %s..%s" % (prop.get("name"), values, low, high))
check(settings >= 14, "found %d mapper settings in the XML (expected at least 14)" % settings)
print("checked %d properties" % settings)
sys.exit(1 if failures else 0)
