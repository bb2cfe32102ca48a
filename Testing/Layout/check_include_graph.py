#!/usr/bin/env python3
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""Checks the project's #include graph: no include cycles and no include against the layering.

A unit is a file name without its extension (itkFoo.h, itkFoo.hxx and itkFoo.cxx are one unit, as ITK's idiom
has the .h and .hxx of a class include each other). Unit A depends on unit B when a file of A includes a header of
B. The graph must have no cycle: no header includes a header (or a unit) that includes it back, directly or
through others. And each layer may include only the layers below it:

    Common   -> Common                Filters -> Filters           Phantoms -> Phantoms, Filters
    Nodes    -> Nodes, Filters, Common                               OpenCL   -> OpenCL, Filters, Common
    IO       -> IO, Nodes, Filters, Common
    Logic    -> Logic, IO, Nodes, Filters, Common, Phantoms, OpenCL
    Widgets  -> Widgets, Logic, IO, Nodes, Filters, Common, Phantoms, OpenCL   (nothing below includes Widgets)
    Applications/VesselReformationViewer -> itself, Widgets and everything below (nothing includes the application)

Usage: check_include_graph.py ROOT      check the tree at ROOT; exit 1 naming every cycle and violation
       check_include_graph.py --self-test  show that a made-up cycle and a made-up violation are found
"""
import os
import re
import sys
import tempfile

from layout_checks import SOURCE_EXTENSIONS, source_files, main as run_check, write_file

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)
ALLOWED = {
    'Logic/Common': {'Logic/Common'},
    'Logic/Filters': {'Logic/Filters'},
    'Logic/Phantoms': {'Logic/Phantoms', 'Logic/Filters'},
    'Logic/Nodes': {'Logic/Nodes', 'Logic/Filters', 'Logic/Common'},
    'OpenCL': {'OpenCL', 'Logic/Filters', 'Logic/Common'},
    'Logic/IO': {'Logic/IO', 'Logic/Nodes', 'Logic/Filters', 'Logic/Common'},
    'Logic': {'Logic', 'Logic/IO', 'Logic/Nodes', 'Logic/Filters', 'Logic/Common', 'Logic/Phantoms', 'OpenCL'},
    'Widgets': {'Widgets', 'Logic', 'Logic/IO', 'Logic/Nodes', 'Logic/Filters', 'Logic/Common', 'Logic/Phantoms',
                'OpenCL'},
    'Applications/VesselReformationViewer': {'Applications/VesselReformationViewer', 'Widgets', 'Logic', 'Logic/IO',
                                             'Logic/Nodes', 'Logic/Filters', 'Logic/Common', 'Logic/Phantoms',
                                             'OpenCL'},
}
SCANNED = ('Logic', 'OpenCL', 'Module', 'Widgets', 'Applications', 'Testing')


def unit_of(path):
    name = os.path.basename(path)
    for extension in sorted(SOURCE_EXTENSIONS, key=len, reverse=True):
        if name.endswith(extension):
            return name[: -len(extension)]
    return name


def layer_of(relative):
    folder = os.path.dirname(relative)
    return folder if folder in ALLOWED else None


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
        write('Logic/Filters/itkA.h', '#include "itkA.hxx"\n')
        write('Logic/Filters/itkA.hxx', '#include "itkA.h"\n')
        problems, _ = check(root)
        assert not problems, problems
        # A format reader and the IO front end including each other's headers is one.
        write('Logic/IO/vrReaderIO.h', '#include "vrReaderFormats.h"\n')
        write('Logic/IO/vrReaderFormats.h', '')
        write('Logic/IO/vrReaderFormats.cxx', '#include "vrReaderIO.h"\n')
        problems, _ = check(root)
        assert any('include cycle between vrReaderFormats, vrReaderIO' in p for p in problems), problems
        # A filter that includes the logic breaks the layering.
        write('Logic/vrLogic.h', '')
        write('Logic/Filters/itkB.cxx', '#include "vrLogic.h"\n')
        problems, _ = check(root)
        assert any('Logic/Filters/itkB.cxx includes Logic/vrLogic.h' in p for p in problems), problems
        # A module widget that includes the viewer's window: the widgets must stand without the application.
        write('Applications/VesselReformationViewer/vrWindow.h', '#include "vrPanel.h"\n')
        write('Widgets/vrPanel.h', '')
        write('Widgets/vrPanel.cxx', '#include "vrWindow.h"\n')
        problems, _ = check(root)
        assert any('Widgets/vrPanel.cxx includes Applications/VesselReformationViewer/vrWindow.h' in p
                   for p in problems), problems
    print('self-test: a made-up include cycle and two made-up layering violations were found')
    return 0


if __name__ == '__main__':
    sys.exit(run_check(sys.argv[1:], __doc__, check, self_test, 'no include cycle, layering respected'))
