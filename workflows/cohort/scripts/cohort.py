#!/usr/bin/env python3
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""The cohort workflow's steps, shared by the Snakefile and the Slurm array job (slurm/cohort-array.sbatch).

A case is one row of the manifest (CSV: case, volume, centerlines, segmentation, branch). Its steps run the
command-line modules, each writing its files whole (the modules stage their outputs) into <output>/work/<case>/:
  centerlines   ExtractCenterlines on the segmentation, when the row gives no centerlines
  tree-<angle>  VesselReformation at each angle: CPR (NRRD) and its picture (PNG)
  vessel        VesselPathReformation of the branch asked for (0 or empty: the longest path): CPR, lumen table
Then the case is published: its files and case.json (every value the modules returned) are laid out in a hidden
folder beside <output>/cases/<case> and renamed into place, so that a case folder appears whole or not at all.
The cohort table (cohort.csv, one row per published case) and failed.csv (case, step, message) come last.

Usage (the Slurm array job runs `case`; the Snakefile imports this file and runs `publish` and `table`):
  cohort.py case --config CONFIG.yaml --index N     run every missing step of manifest row N (0-based), publish
  cohort.py publish --config CONFIG.yaml --case ID  publish a case whose steps have all run
  cohort.py table --config CONFIG.yaml              write cohort.csv and failed.csv from what is published
(--settings JSON instead of --config: the settings as the Snakefile resolved them.)
"""
import argparse
import csv
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

CASE_ID = re.compile(r'^[A-Za-z0-9][A-Za-z0-9._-]*$')
MANIFEST_COLUMNS = ('case', 'volume', 'centerlines', 'segmentation', 'branch')

# The defaults of every setting (config.yaml documents them).
DEFAULTS = {
    'manifest': 'manifest.csv',
    'output': 'results',
    'modules': '',
    'angles': [0, 90],
    'tree': {'size': '512,1024', 'iterations': 500, 'solver': 'jacobi', 'up': 'auto', 'arguments': ''},
    'vessel': {'width': 40, 'arguments': ''},
    'threads': 1,
    'resources': {'centerlines': {'mem_mb': 4000, 'runtime': 30}, 'tree': {'mem_mb': 4000, 'runtime': 20},
                  'vessel': {'mem_mb': 3000, 'runtime': 20}},
}

# The cohort table's columns: the case, then values the modules returned (name in the table: module's name).
TABLE_COLUMNS = [
    ('case', None),
    ('branches', ('tree', 'numberOfBranches')),   # the first angle's tree
    ('centerlines', ('inputs', 'centerlines_source')),
    ('path_length_mm', ('vessel', 'pathLength')),
    ('lumen_source', ('vessel', 'lumenSource')),
    ('mld_mm', ('vessel', 'minimalLumenDiameter')),
    ('mld_arc_length_mm', ('vessel', 'minimalLumenDiameterArcLength')),
    ('mla_mm2', ('vessel', 'minimalLumenArea')),
    ('reference_diameter_mm', ('vessel', 'referenceDiameter')),
    ('diameter_stenosis_percent', ('vessel', 'diameterStenosis')),
    ('area_stenosis_percent', ('vessel', 'areaStenosis')),
    ('cad_rads', ('vessel', 'cadRads')),
    ('sections_outside_segmentation', ('vessel', 'sectionsOutsideSegmentation')),
]


class ManifestError(ValueError):
    """A manifest that cannot be run, naming the file, the row and the column."""


def merged(defaults, given):
    """The defaults with the given values over them, nested dicts merged key by key."""
    result = json.loads(json.dumps(defaults))
    for key, value in (given or {}).items():
        result[key] = merged(result[key], value) if isinstance(value, dict) and isinstance(result.get(key), dict) \
            else value
    return result


def settings(config):
    """The configuration with every default filled in."""
    merged_config = merged(DEFAULTS, config)
    merged_config['angles'] = [angle_text(angle) for angle in merged_config['angles']]
    return merged_config


def angle_text(angle):
    """An angle as the file names write it: 30, 22.5, -45."""
    value = float(angle)
    return str(int(value)) if value == int(value) else repr(value)


def read_manifest(path):
    """The manifest's rows as dicts (paths made absolute against the manifest's folder); ManifestError otherwise."""
    if not os.path.isfile(path):
        raise ManifestError(f'manifest {path}: no such file')
    folder = os.path.dirname(os.path.abspath(path))
    with open(path, newline='', encoding='utf-8') as file:
        reader = csv.DictReader(file)
        columns = [name.strip() for name in reader.fieldnames or []]
        if 'case' not in columns or 'volume' not in columns:
            raise ManifestError(f'manifest {path}: needs the columns case and volume, and centerlines or '
                                f'segmentation (has {", ".join(columns) or "none"})')
        unknown = [name for name in columns if name not in MANIFEST_COLUMNS]
        if unknown:
            raise ManifestError(f'manifest {path}: unknown column {", ".join(unknown)} '
                                f'(the columns are {", ".join(MANIFEST_COLUMNS)})')
        cases = []
        seen = set()
        for number, raw in enumerate(reader, start=2):
            row = {key.strip(): (value or '').strip() for key, value in raw.items() if key}
            where = f'manifest {path}, line {number}'
            case = row.get('case', '')
            if not CASE_ID.match(case):
                raise ManifestError(f'{where}: case "{case}": use letters, digits, ".", "_" and "-" '
                                    '(it names the case\'s folder)')
            if case in seen:
                raise ManifestError(f'{where}: case "{case}" appears twice')
            seen.add(case)
            if not row.get('volume'):
                raise ManifestError(f'{where}: case {case} has no volume')
            if not row.get('centerlines') and not row.get('segmentation'):
                raise ManifestError(f'{where}: case {case} has neither centerlines nor a segmentation')
            branch = row.get('branch') or '0'
            if not re.match(r'^\d+$', branch):
                raise ManifestError(f'{where}: case {case}: branch "{branch}" is not a branch id (0: the longest path)')
            absolute = {key: os.path.normpath(os.path.join(folder, row[key])) if row.get(key) else ''
                        for key in ('volume', 'centerlines', 'segmentation')}
            cases.append({'case': case, 'branch': int(branch), **absolute})
    if not cases:
        raise ManifestError(f'manifest {path}: no case')
    return cases


def work_folder(cfg, case):
    return os.path.join(cfg['output'], 'work', case)


def case_folder(cfg, case):
    return os.path.join(cfg['output'], 'cases', case)


def step_files(cfg, case):
    """Every step's outputs for a case: {step: [files]} (the returned values' file last)."""
    work = work_folder(cfg, case['case'])
    steps = {}
    if not case['centerlines']:
        steps['centerlines'] = [os.path.join(work, 'centerlines.vtp'), os.path.join(work, 'centerlines.returns')]
    for angle in cfg['angles']:
        steps[f'tree-{angle}'] = [os.path.join(work, f'tree-{angle}.nrrd'), os.path.join(work, f'tree-{angle}.png'),
                                  os.path.join(work, f'tree-{angle}.returns')]
    steps['vessel'] = [os.path.join(work, 'vessel-cpr.nrrd'), os.path.join(work, 'vessel-lumen.csv'),
                       os.path.join(work, 'vessel.returns')]
    return steps


def centerlines_of(cfg, case):
    return case['centerlines'] or os.path.join(work_folder(cfg, case['case']), 'centerlines.vtp')


def module(cfg, name):
    return os.path.join(cfg['modules'], name) if cfg['modules'] else name


def step_command(cfg, case, step):
    """The command line (a list) of one step of a case."""
    files = step_files(cfg, case)[step]
    if step == 'centerlines':
        return [module(cfg, 'ExtractCenterlines'), case['segmentation'], files[0], '--returnparameterfile', files[1]]
    if step.startswith('tree-'):
        tree = cfg['tree']
        return ([module(cfg, 'VesselReformation'), case['volume'], centerlines_of(cfg, case), files[0],
                 '--angle', step[len('tree-'):], '--up', str(tree['up']), '--size', str(tree['size']),
                 '--iterations', str(tree['iterations']), '--solver', str(tree['solver']), '--outputPNG', files[1],
                 '--returnparameterfile', files[2]] + shlex.split(str(tree['arguments'])))
    if step == 'vessel':
        command = [module(cfg, 'VesselPathReformation'), case['volume'], centerlines_of(cfg, case), files[0],
                   '--branch', str(case['branch']), '--width', str(cfg['vessel']['width']),
                   '--outputLumenTable', files[1], '--returnparameterfile', files[2]]
        if case['segmentation']:
            command += ['--segmentation', case['segmentation']]
        return command + shlex.split(str(cfg['vessel']['arguments']))
    raise ValueError(f'unknown step {step}')


def step_environment(cfg):
    """The modules' threads: ITK's and the relaxation's thread count (one job per core by default)."""
    environment = dict(os.environ)
    environment['ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS'] = str(cfg['threads'])
    return environment


def read_returns(path):
    """A module's returned values (3D Slicer's "name = value" lines), numbers as numbers."""
    values = {}
    with open(path, encoding='utf-8') as file:
        for line in file:
            if '=' in line:
                name, value = (part.strip() for part in line.split('=', 1))
                values[name] = number_or_text(value)
    return values


def number_or_text(value):
    if value == '':
        return None
    try:
        number = float(value)
    except ValueError:
        return value
    return int(number) if re.match(r'^-?\d+$', value) else number


def publish_case(cfg, case):
    """Lays out a case's files and case.json in a hidden folder beside cases/<case> and renames it into place: the
    case appears whole or not at all (an earlier publication of the case is replaced as a whole)."""
    steps = step_files(cfg, case)
    record = {'case': case['case'],
              'inputs': {'volume': case['volume'], 'centerlines': case['centerlines'],
                         'segmentation': case['segmentation'], 'branch': case['branch'],
                         'centerlines_source': 'given' if case['centerlines'] else 'extracted'},
              'angles': cfg['angles'], 'files': []}
    final = case_folder(cfg, case['case'])
    parent = os.path.dirname(final)
    os.makedirs(parent, exist_ok=True)
    staging = tempfile.mkdtemp(prefix=f'.{case["case"]}.', dir=parent)
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(staging, 0o777 & ~umask)   # a folder like any other, not mkdtemp's private one
    try:
        for step, files in steps.items():
            returns = read_returns(files[-1])
            if step.startswith('tree-'):
                record.setdefault('trees', {})[step[len('tree-'):]] = returns
            else:
                record[step] = returns
            for path in files[:-1]:
                name = os.path.basename(path)
                shutil.copy2(path, os.path.join(staging, name))
                record['files'].append(name)
        write_json(os.path.join(staging, 'case.json'), record)
        previous = None
        if os.path.exists(final):
            previous = tempfile.mkdtemp(prefix=f'.{case["case"]}.old.', dir=parent)
            os.rename(final, os.path.join(previous, 'case'))
        os.rename(staging, final)
        if previous:
            shutil.rmtree(previous)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise


def write_json(path, value):
    with open(path, 'w', encoding='utf-8') as file:
        json.dump(value, file, indent=2, sort_keys=True)
        file.write('\n')


def write_atomically(path, write):
    """Writes a file through a temporary beside it, renamed into place."""
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix='.' + os.path.basename(path) + '.', dir=folder)
    try:
        with os.fdopen(handle, 'w', newline='', encoding='utf-8') as file:
            write(file)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise


def failure_of(cfg, case):
    """(step, message) of a case's failed step, from its log; None when no step failed."""
    logs = os.path.join(cfg['output'], 'logs', case['case'])
    for step in step_files(cfg, case):
        log = os.path.join(logs, f'{step}.log')
        if not os.path.exists(log):
            continue
        with open(log, encoding='utf-8', errors='replace') as file:
            lines = [line.strip() for line in file if line.strip()]
        errors = [line for line in lines if ': error: ' in line or line.startswith('error')]
        if errors:
            return step, errors[-1]
    return None


def write_tables(cfg, cases):
    """Writes cohort.csv (a row per published case) and failed.csv (case, step, message) under the output folder;
    returns the failures."""
    rows, failures = [], []
    for case in cases:
        record_path = os.path.join(case_folder(cfg, case['case']), 'case.json')
        if os.path.exists(record_path):
            with open(record_path, encoding='utf-8') as file:
                record = json.load(file)
            row = {}
            trees = record.get('trees', {})
            record['tree'] = trees.get(str(record.get('angles', [''])[0]), {})
            for column, source in TABLE_COLUMNS:
                value = record['case'] if source is None else record.get(source[0], {}).get(source[1])
                row[column] = '' if value is None else value
            rows.append(row)
        else:
            failure = failure_of(cfg, case)
            step, message = failure if failure else ('', 'not finished (no step failed: run the workflow again)')
            failures.append({'case': case['case'], 'step': step, 'message': message})

    def cohort(file):
        writer = csv.DictWriter(file, fieldnames=[column for column, _ in TABLE_COLUMNS], lineterminator='\n')
        writer.writeheader()
        writer.writerows(rows)

    def failed(file):
        writer = csv.DictWriter(file, fieldnames=['case', 'step', 'message'], lineterminator='\n')
        writer.writeheader()
        writer.writerows(failures)

    write_atomically(os.path.join(cfg['output'], 'cohort.csv'), cohort)
    write_atomically(os.path.join(cfg['output'], 'failed.csv'), failed)
    return failures


def run_case(cfg, case):
    """Runs the missing steps of a case in order and publishes it (the Slurm array job's work for one row); a case
    published already is left as it is."""
    if os.path.exists(os.path.join(case_folder(cfg, case['case']), 'case.json')):
        return 0
    logs = os.path.join(cfg['output'], 'logs', case['case'])
    os.makedirs(logs, exist_ok=True)
    os.makedirs(work_folder(cfg, case['case']), exist_ok=True)
    for step, files in step_files(cfg, case).items():
        if all(os.path.exists(path) for path in files):
            continue
        with open(os.path.join(logs, f'{step}.log'), 'w', encoding='utf-8') as log:
            status = subprocess.call(step_command(cfg, case, step), stdout=log, stderr=subprocess.STDOUT,
                                     env=step_environment(cfg))
        if status != 0:
            failure = failure_of(cfg, case)
            print(f'case {case["case"]}: step {step} failed: {failure[1] if failure else "exit status " + str(status)}',
                  file=sys.stderr)
            return status
    publish_case(cfg, case)
    return 0


def load_config(path):
    import yaml  # Debian's python3-yaml (Snakemake brings it)
    with open(path, encoding='utf-8') as file:
        cfg = settings(yaml.safe_load(file))
    # Relative paths in the configuration are relative to it, as Snakemake's --directory would make them.
    folder = os.path.dirname(os.path.abspath(path))
    for key in ('manifest', 'output', 'modules'):
        if cfg[key] and not os.path.isabs(cfg[key]):
            cfg[key] = os.path.normpath(os.path.join(folder, cfg[key]))
    return cfg


def main(arguments=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('command', choices=('case', 'publish', 'table'))
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument('--config', help='the settings file (YAML, as config.yaml)')
    source.add_argument('--settings', help='the settings as JSON, every default filled in')
    parser.add_argument('--index', type=int, help='the manifest row, 0-based (SLURM_ARRAY_TASK_ID)')
    parser.add_argument('--case', help='the case to publish')
    options = parser.parse_args(arguments)
    cfg = load_config(options.config) if options.config else settings(json.loads(options.settings))
    try:
        cases = read_manifest(cfg['manifest'])
    except ManifestError as error:
        print(f'cohort: {error}', file=sys.stderr)
        return 2
    if options.command == 'publish':
        chosen = [case for case in cases if case['case'] == options.case]
        if not chosen:
            print(f'cohort: no case "{options.case}" in the manifest', file=sys.stderr)
            return 2
        publish_case(cfg, chosen[0])
        return 0
    if options.command == 'table':
        failures = write_tables(cfg, cases)
        for failure in failures:
            print(f'case {failure["case"]}: {failure["step"]}: {failure["message"]}', file=sys.stderr)
        return 1 if failures else 0
    if options.index is None or not 0 <= options.index < len(cases):
        print(f'cohort: --index must be 0 to {len(cases) - 1} (the manifest has {len(cases)} cases)', file=sys.stderr)
        return 2
    return run_case(cfg, cases[options.index])


if __name__ == '__main__':
    sys.exit(main())
