"""The [physics] keys of the options the benchmark scripts compare, once for all of them: each a
dict of case-file key to TOML value text, combined with {**A, **B} (docs/method.md names them)."""

# From 2026-12-07 (session 13) the defaults renormalise the gradient ("khayyer2011-strain"): the
# rows each script measured before then with "the defaults" (or the defaults with one change) are
# reproduced with PLAIN added, and each script's last row is those defaults.
PLAIN = {"gradient_renormalisation": '"none"'}
STRAIN = {"gradient_renormalisation": '"khayyer2011-strain"'}
FREE_SLIP = {"artificial_viscosity_walls": '"free-slip"'}
WALL_FRICTION = {"wall_friction": '"spalding1961"'}
# The flume's side walls of Lobovsky et al.'s tank, 150 mm apart (1610 x 150 x 600 mm).
SIDE_WALLS_LOBOVSKY = {"side_wall_friction": '"spalding1961"', "flume_width": "0.15"}
# The dynamic particle collision between fluid particles (Jandaghian et al. 2021), the default
# from 2026-12-08 (session 15) with particle_collision_min_pressure = 0: the rows measured before
# then with "the defaults" read NO_COLLISION added (each script's row "defaults before session
# 15"); PARTICLE_COLLISION rows name the values they were measured with.
PARTICLE_COLLISION = {"particle_collision": '"jandaghian2021"'}
NO_COLLISION = {"particle_collision": '"none"'}
# The scheme of commit 3a85288's [physics] (CaseSpec.h's use_scheme_3a85288; its fluid's wall
# clearance is a [particles] key, which these rows leave at the default).
OLD = {"negative_pressure": '"zero"', "number_density": '"summation"',
       "free_surface": '"koshizuka1996"', "shifting": '"none"',
       "wall_density": '"n0"', "gradient_renormalisation": '"none"', **NO_COLLISION}
