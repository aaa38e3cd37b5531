"""The ParaView plugin's server-manager XML of the map and the sphere embedding, as the
generator writes it from the list of settings: every setting a property with the list's
command, default, range, documentation, panel and topic, and no setting written by hand."""

import os
import subprocess
import xml.etree.ElementTree as ElementTree

import pytest

import surfacemaps

S = surfacemaps.vtkSurfaceMapsSettings
GENERATOR = os.environ["SURFACEMAPS_GENERATE_XML"]
PLUGIN = os.environ["SURFACEMAPS_PARAVIEW_PLUGIN"]
PROXIES = {S.MAP_SETTINGS: ("SurfaceMapFilter", "SurfaceMap"),
           S.SPHERE_EMBEDDING_SETTINGS: ("SphereEmbeddingFilter", "SphereEmbedding")}


def generated(tmp_path, name):
    out = tmp_path / (name + ".xml")
    r = subprocess.run([GENERATOR, os.path.join(PLUGIN, name + ".xml.in"), str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return ElementTree.parse(out).getroot()


@pytest.mark.parametrize("table", sorted(PROXIES))
def test_every_setting_is_a_property_as_the_list_says(tmp_path, table):
    template, proxy_name = PROXIES[table]
    proxy = generated(tmp_path, template).find(f".//SourceProxy[@name='{proxy_name}']")
    properties = {p.get("name"): p for p in proxy if p.tag.endswith("VectorProperty")}
    groups = {p.get("name"): g.get("label") for g in proxy.iter("PropertyGroup") for p in g}
    for i in range(S.GetNumberOfSettings(table)):
        name = S.GetName(table, i)
        p = properties[name]
        kind = S.GetType(table, i)
        assert p.tag == ("DoubleVectorProperty" if kind == S.REAL else "IntVectorProperty"), name
        assert p.get("command") == "Set" + name
        assert float(p.get("default_values")) == S.GetDefault(table, i), name
        assert (p.get("panel_visibility") == "advanced") != S.IsBasic(table, i), name
        if kind in (S.REAL, S.COUNT):
            domain = p.find("DoubleRangeDomain" if kind == S.REAL else "IntRangeDomain")
            assert (float(domain.get("min")), float(domain.get("max"))) == \
                (S.GetMinimum(table, i), S.GetMaximum(table, i)), name
        elif kind == S.CHOICE:
            entries = [e.get("text") for e in p.find("EnumerationDomain")]
            assert entries == S.GetChoices(table, i).split("|"), name
        doc = p.find("Documentation").text
        assert doc == f"{S.GetDescription(table, i)} (Command line: --{S.GetFlag(table, i)}.)", name
        assert groups[name] == S.GetTopic(table, i), name


def test_no_setting_is_written_by_hand():
    names = {S.GetName(t, i) for t in PROXIES for i in range(S.GetNumberOfSettings(t))}
    for template in ("SurfaceMaps.xml", "SurfaceMapFilter.xml.in", "SphereEmbeddingFilter.xml.in"):
        root = ElementTree.parse(os.path.join(PLUGIN, template)).getroot()
        written = {p.get("name") for p in root.iter() if p.tag.endswith("VectorProperty")}
        assert not written & names, template


def test_a_template_without_a_marker_is_an_error(tmp_path):
    template = tmp_path / "plain.xml.in"
    template.write_text("<ServerManagerConfiguration/>\n")
    r = subprocess.run([GENERATOR, str(template), str(tmp_path / "out.xml")], capture_output=True, text=True)
    assert r.returncode == 1 and "@EMBEDDING_SETTINGS@" in r.stderr
