#!/usr/bin/env python3
"""Checks that a Grasshopper plugin compiled against the compile-only facades binds only to SDK members that exist.

Every member reference, type reference and overridden method of the built .gha that points into Grasshopper,
RhinoCommon or GH_IO must be verified: listed in grasshopper-members.txt (member references recorded in real plugins
compiled against the real Grasshopper.dll; an entry cut before its parameter list vouches for the member name) or in
verified-members.txt (members checked against the real assemblies, each with its evidence). Anything else fails the
check, naming the member: a facade that declares something the real SDK does not (or declares it elsewhere, such as an
indexer without its real name) cannot slip into a shipped .gha.

Usage: check_members.py GHA FACADE_DIR MEMBER_TOOL_EXE RECORDED_LIST VERIFIED_LIST
"""
import os
import re
import subprocess
import sys

SDK = ("Grasshopper", "RhinoCommon", "GH_IO")
SDK_TYPE = re.compile(r"\[(?:Grasshopper|RhinoCommon|GH_IO)\][A-Za-z0-9_.`/]+")


def strip_keywords(text):
    return re.sub(r"\b(?:class|valuetype) ", "", text).replace("[out] ", "").replace("[in] ", "")


def strip_generic_arguments(owner):
    """GH_Goo`1<class X> -> GH_Goo`1 (a member exists or not whatever the instantiation)."""
    depth, out = 0, []
    for ch in owner:
        if ch == "<":
            depth += 1
        elif ch == ">":
            depth -= 1
        elif depth == 0:
            out.append(ch)
    return "".join(out)


def split_parameters(signature):
    """The parameter list "(...)" at the end of a method signature, or None for a field."""
    signature = signature.rstrip()
    if not signature.endswith(")"):
        return None
    depth = 0
    for i in range(len(signature) - 1, -1, -1):
        if signature[i] == ")":
            depth += 1
        elif signature[i] == "(":
            depth -= 1
            if depth == 0:
                return signature[i:]
    return None


def monodis(args, facades):
    env = dict(os.environ, MONO_PATH=facades)
    return subprocess.run(["monodis"] + args, env=env, check=True, capture_output=True, text=True).stdout


def member_references(gha, facades):
    """Canonical [Asm]Owner::Name(params) of every member reference into the SDK."""
    refs, name = set(), None
    lines = monodis(["--memberref", gha], facades).splitlines()
    for i, line in enumerate(lines):
        header = re.match(r"^\d+: \w+\[\d+\] (.+)$", line)
        if header:
            name = header.group(1).strip()
            continue
        resolved = re.match(r"^\s+Resolved: (.+)$", line)
        if not resolved or name is None:
            continue
        target = strip_keywords(resolved.group(1).strip())
        if not target.endswith("." + name) or not target.startswith(tuple("[%s]" % a for a in SDK)):
            continue
        owner = strip_generic_arguments(target[: -len(name) - 1])
        signature = lines[i + 1].strip() if i + 1 < len(lines) else ""
        if "BROKEN" in signature:
            sys.exit("monodis could not resolve a type of " + owner + "::" + name + " (are the facades in " + facades + "?)")
        parameters = split_parameters(strip_keywords(signature.replace("Signature:", "", 1)))
        refs.add(owner + "::" + name + (parameters if parameters is not None else ""))
    return refs


def type_references(gha, facades):
    types = set()
    for line in monodis(["--typeref", gha], facades).splitlines():
        match = re.match(r"^\d+: (\[(?:%s)\]\S+)$" % "|".join(SDK), line.strip())
        if match:
            types.add(match.group(1))
    return types


def overrides(gha, facades, tool):
    env = dict(os.environ, MONO_PATH=facades)
    out = subprocess.run(["mono", tool, "overrides", gha], env=env, check=True, capture_output=True, text=True).stdout
    return {line.strip() for line in out.splitlines() if line.strip()}


def entries(path):
    for raw in open(path, encoding="utf-8"):
        line = raw.split("#", 1)[0].strip()
        if line:
            yield line


def load_lists(recorded_path, verified_path):
    """(exact members, member names vouched for by cut entries, known types)."""
    exact, names, types = set(), set(), set()
    for line in entries(recorded_path):
        owner, _, member = line.partition("::")
        if not member or owner.count("<") != owner.count(">"):
            continue  # cut inside a generic instantiation's type arguments (List<GH_Path>): says nothing about the SDK
        owner = strip_generic_arguments(owner)
        types.add(owner)
        if "(" in member:
            name, params = member.split("(", 1)
            name = re.sub(r"<.*$", "", name)
            exact.add(owner + "::" + name + "(" + params)
            types.update(SDK_TYPE.findall(params))
        else:
            names.add(owner + "::" + re.sub(r"<.*$", "", member))
    for line in entries(verified_path):
        if "::" not in line:
            types.add(line)
            continue
        exact.add(line)
        types.add(line.split("::", 1)[0])
        types.update(SDK_TYPE.findall(line.split("::", 1)[1]))
    return exact, names, types


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    gha, facades, tool, recorded, verified = sys.argv[1:]
    exact, names, types = load_lists(recorded, verified)
    refs, overridden, typerefs = member_references(gha, facades), overrides(gha, facades, tool), type_references(gha, facades)

    def verified_member(member):
        return member in exact or member.split("(", 1)[0] in names

    problems = ["unverified member reference: " + m for m in sorted(refs) if not verified_member(m)]
    problems += ["unverified override: " + m for m in sorted(overridden) if not verified_member(m)]
    problems += ["unverified type reference: " + t for t in sorted(typerefs) if t not in types]
    for problem in problems:
        print(problem)
    print("%d member references, %d overrides, %d type references into %s: %d unverified"
          % (len(refs), len(overridden), len(typerefs), "/".join(SDK), len(problems)))
    if problems:
        print("Check each against the real assemblies (csharp/facades/check/README.md) and record it in " + verified
              + " with its evidence, or fix the facade.")
        sys.exit(1)


if __name__ == "__main__":
    main()
