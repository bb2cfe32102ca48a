# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""What the layout checks (check_include_graph.py, check_single_copies.py) share: one walk over the project's C++
sources, the command line, and writing the made-up trees of their self-tests."""
import os
import sys

SOURCE_EXTENSIONS = ('.h', '.hxx', '.cxx', '.h.in', '.cxx.in')
# Folders that hold inputs, not code (the fuzzers' corpora).
NOT_SOURCES = ('corpus',)


def source_files(root, tops, skipped=()):
    """Yields the path, relative to root with '/' between folders, of every source under root/<top> for each of
    tops, folder by folder in the order os.walk gives them and by name within a folder; a folder whose relative path
    starts with one of skipped is not entered."""
    for top in tops:
        for directory, subdirectories, names in os.walk(os.path.join(root, top)):
            relative_directory = os.path.relpath(directory, root).replace(os.sep, '/')
            if relative_directory.startswith(tuple(skipped)):
                subdirectories[:] = []
                continue
            subdirectories[:] = [d for d in subdirectories if d not in NOT_SOURCES]
            for name in sorted(names):
                if name.endswith(SOURCE_EXTENSIONS):
                    yield f'{relative_directory}/{name}'


def write_file(root, relative, text):
    """Writes a made-up source file of a self-test, making its folders."""
    path = os.path.join(root, relative)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as file:
        file.write(text)


def main(arguments, usage, check, self_test, passed):
    """The checks' command line: ROOT checks the tree there (exit 1 naming every problem, else prints passed with the
    number of files read); --self-test runs self_test(). check(root) returns (problems, files read)."""
    if arguments == ['--self-test']:
        return self_test()
    if len(arguments) != 1:
        print(usage, file=sys.stderr)
        return 2
    problems, count = check(arguments[0])
    for problem in problems:
        print('error: ' + problem, file=sys.stderr)
    if problems:
        return 1
    print(f'{count} source files: {passed}')
    return 0
