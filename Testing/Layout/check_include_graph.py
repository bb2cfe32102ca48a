#!/usr/bin/env python3
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""Checks the project's #include graph: no include cycles and no include against the layering.

A unit is a file name without its extension (itkFoo.h, itkFoo.hxx and itkFoo.cxx are one unit, as ITK's idiom
has the .h and .hxx of a class include each other). Unit A depends on unit B when a file of A includes a header of
B. The graph must have no cycle: no header includes a header (or a unit) that includes it back, directly or
through others. And each folder (a "room") may include only the rooms below it:

    Logic/Common                          itself
    Logic/Filters/<concern>               itself and the concerns it builds on: Threading and Centerlines stand
                                          alone; Depth builds on Centerlines; Relax and Relax/Steady on each other
                                          and Threading; Resample on Depth; VesselPath on Centerlines, Depth and
                                          Resample; Lumen on VesselPath and what it builds on
    Logic/Phantoms                        itself, the filters
    Logic/Nodes, OpenCL                   themselves, the filters, Common
    Logic/IO and its subfolders           themselves, each other, Nodes, the filters, Common
    Logic/Shared, Logic/Display           themselves, IO and below
    Logic/Centerlines                     itself, Shared, IO and below
    Logic/Inputs                          itself, Centerlines, Display, Shared, Phantoms, IO and below
    Logic/TreeReformation                 itself, Inputs and below, OpenCL (never Logic/VesselPath)
    Logic/VesselPath                      itself, Inputs and below (never Logic/TreeReformation)
    Widgets/Common                        itself and the logic
    Widgets/Tree, Widgets/VesselPath      themselves, Widgets/Common and the logic (not each other)
    Applications/VesselReformationViewer  itself, the widgets and everything below (nothing includes it)
    Python/Bindings                       itself and the logic (the Python package's extension; nothing includes it)

A source file in a folder of Logic, OpenCL, Widgets, Applications or Python that no rule names is reported too: a new
room needs its rule here (and its paragraph in docs/layout.md).

Usage: check_include_graph.py ROOT      check the tree at ROOT; exit 1 naming every cycle and violation
       check_include_graph.py --self-test  show that a made-up cycle, made-up violations and an unknown room are found
"""
import os
import re
import sys
import tempfile

from layout_checks import SOURCE_EXTENSIONS, source_files, main as run_check, write_file

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def _filters(*concerns):
    return {'Logic/Filters/' + concern for concern in concerns}


FILTERS = _filters('Threading', 'Centerlines', 'Depth', 'Relax', 'Relax/Steady', 'Resample', 'VesselPath', 'Lumen')
IO = {'Logic/IO', 'Logic/IO/DICOM', 'Logic/IO/Volumes', 'Logic/IO/Centerlines', 'Logic/IO/Outputs'}
BELOW_IO = IO | {'Logic/Nodes', 'Logic/Common'} | FILTERS
LOGIC_BASE = {'Logic/Inputs', 'Logic/Centerlines', 'Logic/Display', 'Logic/Shared', 'Logic/Phantoms'} | BELOW_IO
LOGIC = LOGIC_BASE | {'Logic/TreeReformation', 'Logic/VesselPath', 'OpenCL'}
WIDGETS = {'Widgets/Common', 'Widgets/Tree', 'Widgets/VesselPath'}
ALLOWED = {
    'Logic/Common': {'Logic/Common'},
    'Logic/Filters/Threading': _filters('Threading'),
    'Logic/Filters/Centerlines': _filters('Centerlines'),
    'Logic/Filters/Depth': _filters('Depth', 'Centerlines'),
    'Logic/Filters/Relax': _filters('Relax', 'Relax/Steady', 'Threading'),
    'Logic/Filters/Relax/Steady': _filters('Relax/Steady', 'Relax', 'Threading'),
    'Logic/Filters/Resample': _filters('Resample', 'Depth', 'Centerlines'),
    'Logic/Filters/VesselPath': _filters('VesselPath', 'Resample', 'Depth', 'Centerlines'),
    'Logic/Filters/Lumen': _filters('Lumen', 'VesselPath', 'Resample', 'Depth', 'Centerlines'),
    'Logic/Phantoms': {'Logic/Phantoms'} | FILTERS,
    'Logic/Nodes': {'Logic/Nodes', 'Logic/Common'} | FILTERS,
    'OpenCL': {'OpenCL', 'Logic/Common'} | FILTERS,
    **{folder: BELOW_IO for folder in IO},
    'Logic/Shared': {'Logic/Shared'} | BELOW_IO,
    'Logic/Display': {'Logic/Display'} | BELOW_IO,
    'Logic/Centerlines': {'Logic/Centerlines', 'Logic/Shared'} | BELOW_IO,
    'Logic/Inputs': LOGIC_BASE,
    'Logic/TreeReformation': LOGIC_BASE | {'Logic/TreeReformation', 'OpenCL'},
    'Logic/VesselPath': LOGIC_BASE | {'Logic/VesselPath'},
    'Widgets/Common': {'Widgets/Common'} | LOGIC,
    'Widgets/Tree': {'Widgets/Tree', 'Widgets/Common'} | LOGIC,
    'Widgets/VesselPath': {'Widgets/VesselPath', 'Widgets/Common'} | LOGIC,
    'Applications/VesselReformationViewer': {'Applications/VesselReformationViewer'} | WIDGETS | LOGIC,
    'Python/Bindings': {'Python/Bindings'} | LOGIC,
}
LAYERED = ('Logic', 'OpenCL', 'Widgets', 'Applications', 'Python')
SCANNED = ('Logic', 'OpenCL', 'Module', 'Widgets', 'Applications', 'Python', 'Testing')


def unit_of(path):
    name = os.path.basename(path)
    for extension in sorted(SOURCE_EXTENSIONS, key=len, reverse=True):
        if name.endswith(extension):
            return name[: -len(extension)]
    return name


def layer_of(relative):
    folder = os.path.dirname(relative)
    return folder if folder in ALLOWED else None


def unknown_room(relative):
    """True for a source in a layered folder that no rule names."""
    return relative.startswith(tuple(top + '/' for top in LAYERED)) and layer_of(relative) is None


def scan(root):
    """Returns {relative path: [included names]} for the project's sources under root."""
    files = {}
    for relative in source_files(root, SCANNED):
        with open(os.path.join(root, relative), encoding='utf-8', errors='replace') as file:
            files[relative] = INCLUDE.findall(file.read())
    return files


def check(root):
    files = scan(root)
    headers = {}
    for relative in files:
        headers.setdefault(os.path.basename(relative), []).append(relative)
    problems = []
    graph = {}
    witness = {}
    for relative in sorted(files):
        if unknown_room(relative):
            problems.append(f'{relative}: the folder {os.path.dirname(relative)} has no layering rule '
                            '(Testing/Layout/check_include_graph.py) and no paragraph in docs/layout.md')
    for relative, includes in sorted(files.items()):
        unit = unit_of(relative)
        graph.setdefault(unit, set())
        for included in includes:
            for target in headers.get(os.path.basename(included), []):
                target_unit = unit_of(target)
                from_layer, to_layer = layer_of(relative), layer_of(target)
                if from_layer and to_layer and to_layer not in ALLOWED[from_layer]:
                    problems.append(f'{relative} includes {target}: the {from_layer} layer may include only '
                                    f'{", ".join(sorted(ALLOWED[from_layer]))}')
                if target_unit != unit:
                    graph[unit].add(target_unit)
                    witness.setdefault((unit, target_unit), f'{relative} includes "{included}"')
    for component in strongly_connected(graph):
        if len(component) > 1:
            cycle = sorted(component)
            lines = [witness[(a, b)] for a in cycle for b in cycle if (a, b) in witness]
            problems.append('include cycle between ' + ', '.join(cycle) + ':\n    ' + '\n    '.join(lines))
    return problems, len(files)


def strongly_connected(graph):
    """Tarjan's algorithm, iterative."""
    index, lowlink, on_stack, stack, result, counter = {}, {}, set(), [], [], [0]
    for start in graph:
        if start in index:
            continue
        work = [(start, iter(sorted(graph.get(start, ()))))]
        index[start] = lowlink[start] = counter[0]
        counter[0] += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            advanced = False
            for child in children:
                if child not in index:
                    index[child] = lowlink[child] = counter[0]
                    counter[0] += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                    advanced = True
                    break
                if child in on_stack:
                    lowlink[node] = min(lowlink[node], index[child])
            if advanced:
                continue
            work.pop()
            if work:
                lowlink[work[-1][0]] = min(lowlink[work[-1][0]], lowlink[node])
            if lowlink[node] == index[node]:
                component = set()
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.add(member)
                    if member == node:
                        break
                result.append(component)
    return result


def self_test():
    with tempfile.TemporaryDirectory() as root:
        def write(relative, text):
            write_file(root, relative, text)
        # The ITK idiom alone (a .h and its .hxx) is no cycle.
        write('Logic/Filters/Depth/itkA.h', '#include "itkA.hxx"\n')
        write('Logic/Filters/Depth/itkA.hxx', '#include "itkA.h"\n')
        problems, _ = check(root)
        assert not problems, problems
        # A format reader and the IO front end including each other's headers is one.
        write('Logic/IO/vrReaderIO.h', '#include "vrReaderFormats.h"\n')
        write('Logic/IO/vrReaderFormats.h', '')
        write('Logic/IO/vrReaderFormats.cxx', '#include "vrReaderIO.h"\n')
        problems, _ = check(root)
        assert any('include cycle between vrReaderFormats, vrReaderIO' in p for p in problems), problems
        # A filter that includes the logic breaks the layering.
        write('Logic/TreeReformation/vrLogic.h', '')
        write('Logic/Filters/Depth/itkB.cxx', '#include "vrLogic.h"\n')
        problems, _ = check(root)
        assert any('Logic/Filters/Depth/itkB.cxx includes Logic/TreeReformation/vrLogic.h' in p
                   for p in problems), problems
        # A concern of the filters that includes one it does not build on: the depth filter and the relaxation.
        write('Logic/Filters/Relax/itkRelax.h', '')
        write('Logic/Filters/Depth/itkC.cxx', '#include "itkRelax.h"\n')
        problems, _ = check(root)
        assert any('Logic/Filters/Depth/itkC.cxx includes Logic/Filters/Relax/itkRelax.h' in p
                   for p in problems), problems
        # One feature's logic including the other's: the one-vessel reading stands without the tree's logic.
        write('Logic/VesselPath/vrPath.cxx', '#include "vrLogic.h"\n')
        problems, _ = check(root)
        assert any('Logic/VesselPath/vrPath.cxx includes Logic/TreeReformation/vrLogic.h' in p
                   for p in problems), problems
        # A source in a folder no rule names.
        write('Logic/Misc/vrLoose.cxx', '')
        problems, _ = check(root)
        assert any('Logic/Misc/vrLoose.cxx: the folder Logic/Misc has no layering rule' in p
                   for p in problems), problems
        # A module widget that includes the viewer's window: the widgets must stand without the application.
        write('Applications/VesselReformationViewer/vrWindow.h', '#include "vrPanel.h"\n')
        write('Widgets/Tree/vrPanel.h', '')
        write('Widgets/Tree/vrPanel.cxx', '#include "vrWindow.h"\n')
        problems, _ = check(root)
        assert any('Widgets/Tree/vrPanel.cxx includes Applications/VesselReformationViewer/vrWindow.h' in p
                   for p in problems), problems
    print('self-test: a made-up include cycle, four made-up layering violations and an unknown folder were found')
    return 0


if __name__ == '__main__':
    sys.exit(run_check(sys.argv[1:], __doc__, check, self_test, 'no include cycle, layering respected'))
