#!/usr/bin/env python3
"""The histories of a beam of two planes at the tip, at the observation points and at the
nodes (docs/output.md: /tip/displacement and /tip/velocity (outputs, 2), /points/displacement
and /points/velocity (outputs, points, 2), /field/displacement (snapshots, nodes, 2), y then
z; STEM_tip.dat and STEM_points.dat with the z columns after the planar ones, STEM_field.dat
x t u_y u_z), against the planar run of the same beam.

usage: check_planes_points.py VIBROBEAM

A forced cantilever with two observation points, free of obstacles, runs planar, then with
&beam planes = 2 and its load and initial velocity along y (direction 0) and along z
(direction 90): directions that are multiples of 90 degrees are exact (docs/input.md,
"&beam"), so the plane that carries the data equals the planar run bit for bit and the other
holds exact zeros, in the HDF5 histories and in the text files' columns. Loaded at 30
degrees the beam moves in both planes: the field's last node is the tip (docs/output.md),
so its y and z equal /tip/displacement's bit for bit at every snapshot (field_every = every).
Exit status 0 when every check holds, 1 otherwise (one line per failure), 77 without h5py.
"""
import os
import sys
import tempfile

try:
    import numpy as np
    import h5py
except ImportError:
    print('SKIP: no python3 with h5py (Debian package python3-h5py)')
    sys.exit(77)

from planes_scene import check, failures, run as run_scene


def run(vibrobeam, folder, name, planes='', direction=''):
    result_path = run_scene(vibrobeam, folder, name, planes, direction, output=', text = .true.')
    with h5py.File(result_path, 'r') as result:
        histories = {path: result[path][...] for path in
                     ['tip/displacement', 'tip/velocity', 'points/displacement', 'points/velocity',
                      'field/displacement']}
    text = {kind: np.loadtxt(os.path.join(folder, f'{name}_{kind}.dat'), comments='#', ndmin=2)
            for kind in ['tip', 'points', 'field']}
    return histories, text


def main():
    vibrobeam = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        planar, planar_text = run(vibrobeam, folder, 'planar')
        points = planar['points/displacement'].shape[1]
        check('the planar run has 2 observation points and moves', points == 2 and
              np.abs(planar['points/displacement']).max() > 0)
        for name, direction, carrier in [('along_y', ', direction = 0', 0), ('along_z', ', direction = 90', 1)]:
            turned, turned_text = run(vibrobeam, folder, name, ', planes = 2', direction)
            for path in ['tip/displacement', 'tip/velocity', 'points/displacement', 'points/velocity',
                         'field/displacement']:
                values = turned[path]
                shape = planar[path].shape + (2,)
                check(f'{name}: /{path} has the shape {shape} (y, z last)', values.shape == shape)
                if values.shape != shape:
                    continue
                check(f'{name}: /{path} in the plane of the data equals the planar run bit for bit',
                      np.array_equal(values[..., carrier], planar[path]))
                check(f'{name}: /{path} in the other plane is exactly 0',
                      not np.any(values[..., 1 - carrier]))
            # the text files: the planar columns in their places, the z plane's after them
            for kind, planar_columns in [('tip', planar_text['tip'].shape[1]),
                                         ('points', planar_text['points'].shape[1])]:
                table = turned_text[kind]
                moving = 2 if kind == 'tip' else 2 * points
                check(f'{name}: {name}_{kind}.dat has {planar_columns} + {moving} columns',
                      table.shape == (planar_text[kind].shape[0], planar_columns + moving))
                if table.shape[1] != planar_columns + moving:
                    continue
                reference = planar_text[kind][:, 1:1 + moving]   # u then v, planar
                y_columns = table[:, 1:1 + moving]
                z_columns = table[:, planar_columns:]
                data, other = (y_columns, z_columns) if carrier == 0 else (z_columns, y_columns)
                check(f'{name}: {name}_{kind}.dat, the plane of the data equals the planar columns',
                      np.array_equal(data, reference))
                check(f'{name}: {name}_{kind}.dat, the other plane is 0', not np.any(other))
            # STEM_field.dat: x t u planar, x t u_y u_z with two planes
            table, reference = turned_text['field'], planar_text['field']
            check(f'{name}: {name}_field.dat has the columns x t u_y u_z', table.shape == (reference.shape[0], 4))
            if table.shape == (reference.shape[0], 4):
                check(f'{name}: {name}_field.dat, x, t and the plane of the data equal the planar file',
                      np.array_equal(table[:, [0, 1, 2 + carrier]], reference))
                check(f'{name}: {name}_field.dat, the other plane is 0', not np.any(table[:, 3 - carrier]))
        turned, _ = run(vibrobeam, folder, 'along_30', ', planes = 2', ', direction = 30')
        field_tip, tip = turned['field/displacement'][:, -1, :], turned['tip/displacement']
        check('along_30: the field moves in z (largest |u_z| at the tip '
              f'{np.abs(field_tip[:, 1]).max():.3e} m, in y {np.abs(field_tip[:, 0]).max():.3e} m)',
              np.abs(field_tip[:, 1]).max() > 0.1 * np.abs(field_tip[:, 0]).max())
        check('along_30: the field at the last node equals /tip/displacement in y and z bit for bit',
              field_tip.shape == tip.shape and np.array_equal(field_tip, tip))
    print(f'check_planes_points: {len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
