#!/usr/bin/env python3
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""Checks that the outputs of a reformation have one writer and the filter settings one description.

Outside their homes, the code of the logic, the modules, the widgets and the Python package's extension (comments left
out) may not
- write a logic output node or a surface itself: a call of WriteImage2D or WriteWindowedPNG on
  ConvertVolumeNodeTo...(), or of WriteSurface, belongs to Logic/TreeReformation/vrOutputWriter.cxx (the IO layer
  defines them);
- spell the filter settings as captions do: a string literal that, without its separators (spaces, commas, line
  breaks and digits), reads "steady solver", "mm^-2", "unfiltered (w = 0)" or, after a separator, "iterations"
  (" iterations", not the parameter's name), belongs to Logic/TreeReformation/vrFilterSettingsText.h/.cxx.

Usage: check_single_copies.py ROOT        check the tree at ROOT; exit 1 naming every copy found
       check_single_copies.py --self-test  show that made-up copies of both are found
"""
import os
import re
import sys
import tempfile

from layout_checks import source_files, main as run_check, write_file

SCANNED = ('Logic', 'Module', 'Widgets', 'Applications', 'Python')
# The layers below the logic define the writers and say nothing of captions.
SKIPPED = ('Logic/Common', 'Logic/Filters', 'Logic/IO', 'Logic/Nodes', 'Logic/Phantoms')
WRITER_HOME = 'Logic/TreeReformation/vrOutputWriter.cxx'
SETTINGS_HOMES = tuple('Logic/TreeReformation/vrFilterSettingsText' + extension for extension in ('.h', '.cxx'))

WRITE_CALL = re.compile(r'\b(?:WriteImage2D|WriteWindowedPNG)\s*\(\s*(?:vr::)?ConvertVolumeNodeTo|\bWriteSurface\s*\(')
LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
COMMENT = re.compile(r'//[^\n]*|/\*.*?\*/', re.DOTALL)
SETTINGS_WORDS = {'steady solver', 'mm^-2', 'unfiltered (w = 0)'}


def without_comments(text):
    # String literals first, so that "//" inside one is no comment; comments become blanks of their own lines.
    pieces = re.compile(r'"(?:[^"\\\n]|\\.)*"|//[^\n]*|/\*.*?\*/', re.DOTALL)
    return pieces.sub(lambda m: m.group(0) if m.group(0).startswith('"') else '\n' * m.group(0).count('\n'), text)


def settings_word(literal):
    stripped = re.sub(r'^(?:\\n|[\s,0-9])+|(?:\\n|[\s,0-9])+$', '', literal)
    return stripped in SETTINGS_WORDS or (stripped == 'iterations' and literal != 'iterations')


def check(root):
    problems = []
    count = 0
    for relative in source_files(root, SCANNED, SKIPPED):
        count += 1
        with open(os.path.join(root, relative), encoding='utf-8', errors='replace') as file:
            code = without_comments(file.read())
        for match in WRITE_CALL.finditer(code):
            if relative != WRITER_HOME:
                line = code.count('\n', 0, match.start()) + 1
                problems.append(f'{relative}:{line}: writes a reformation output itself ("{match.group(0)}"); '
                                f'use vr::OutputWriter or vr::WriteOutputs ({WRITER_HOME})')
        for match in LITERAL.finditer(code):
            if relative not in SETTINGS_HOMES and settings_word(match.group(1)):
                line = code.count('\n', 0, match.start()) + 1
                problems.append(f'{relative}:{line}: spells the filter settings ("{match.group(1)}"); '
                                f'use vr::DescribeFilterSettings ({SETTINGS_HOMES[0]})')
    return problems, count


def self_test():
    with tempfile.TemporaryDirectory() as root:
        def write(relative, text):
            write_file(root, relative, text)
        # The homes themselves, comments, and the flag "--iterations" are no copies.
        write(WRITER_HOME, 'WriteSurface(outputs.Surface, path, CoordinateSpace::RAS, CoordinateSpace::LPS);\n')
        write(SETTINGS_HOMES[1], 'text << breakBefore << "steady solver";\n')
        write('Module/A/A.cxx', '// WriteSurface(s, p); " iterations"\napp.add_option("--iterations", n);\n')
        write('Logic/IO/vrSurfaceIO.cxx', 'void WriteSurface(vtkPolyData * s, const std::string & p) {}\n')
        problems, _ = check(root)
        assert not problems, problems
        # A viewer that writes its own surface and a demo that spells its own caption are.
        write('Widgets/vrSave.cxx', 'vr::WriteSurface(outputs.Surface, path, CoordinateSpace::RAS);\n')
        write('Module/Demo/Demo.cxx', 'std::cout << std::to_string(n) + " iterations" << "\\nsteady solver";\n')
        problems, _ = check(root)
        assert any(p.startswith('Widgets/vrSave.cxx:1: writes') for p in problems), problems
        assert sum(p.startswith('Module/Demo/Demo.cxx:1: spells') for p in problems) == 2, problems
    print('self-test: a made-up second writer and two made-up caption copies were found')
    return 0


if __name__ == '__main__':
    sys.exit(run_check(sys.argv[1:], __doc__, check, self_test,
                       'one output writer, one description of the filter settings'))
