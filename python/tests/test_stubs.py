"""The type stubs (dynpos/__init__.pyi) name exactly the keyword arguments each analysis
accepts: the fields of its request, the shared log options and its outputs."""

import ast
import inspect
import os

import pytest

import dynpos
from dynpos import _dynpos

STUBS = os.path.join(os.path.dirname(dynpos.__file__), "__init__.pyi")
LOG_OPTIONS = {"clock_offset", "max_gap", "format", "bag_time", "msg_path", "strict",
               "time_format", "date", "time_order", "jobs"}
REQUESTS = {"identify_step": _dynpos.StepRequest,
            "identify_thrust_map": _dynpos.ThrustMapRequest,
            "identify_agility": _dynpos.AgilityRequest,
            "identify_four_corner": _dynpos.FourCornerRequest,
            "identify_station_keeping": _dynpos.StationKeepingRequest,
            "identify_failure_test": _dynpos.FailureTestRequest,
            "compare_trial": _dynpos.CompareTrialRequest,
            "estimate": _dynpos.EstimateRequest,
            "consequence": _dynpos.ConsequenceRequest,
            "leverarm_gnss": _dynpos.LeverarmGnssRequest,
            "leverarm_mru": _dynpos.LeverarmMruRequest,
            "hybrid_case": _dynpos.HybridCaseRequest,
            "hybrid_vessel": _dynpos.HybridVesselRequest,
            "compare": _dynpos.CompareRequest,
            "capability": _dynpos.CapabilityRequest}


def stub_functions():
    with open(STUBS, encoding="utf-8") as f:
        tree = ast.parse(f.read())
    return {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}


def fields(cls):
    return {name for name in dir(cls()) if not name.startswith("_") and name != "source"}


@pytest.mark.parametrize("name", sorted(REQUESTS))
def test_the_stub_names_every_option_and_no_other(name):
    stub = stub_functions()[name]
    real = inspect.signature(getattr(dynpos, name))
    explicit = [p for p in real.parameters.values() if p.kind is not p.VAR_KEYWORD]
    positional = [a.arg for a in stub.args.args]
    assert positional == [p.name for p in explicit if p.kind is p.POSITIONAL_OR_KEYWORD]
    keywords = {a.arg for a in stub.args.kwonlyargs}
    outputs = {p.name for p in explicit if p.kind is p.KEYWORD_ONLY}
    reads_log = "log" in positional
    expected = fields(REQUESTS[name]) - set(positional) | outputs | (LOG_OPTIONS if reads_log
                                                                    else set())
    assert keywords == expected


def test_every_public_name_has_a_stub():
    stubs = set(stub_functions())
    with open(STUBS, encoding="utf-8") as f:
        classes = {n.name for n in ast.parse(f.read()).body if isinstance(n, ast.ClassDef)}
    assert set(dynpos.__all__) == stubs | classes
