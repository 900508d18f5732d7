"""The [physics] keys of the options the benchmark scripts compare, once for all of them: each a
dict of case-file key to TOML value text, combined with {**A, **B} (docs/method.md names them)."""

STRAIN = {"gradient_renormalisation": '"khayyer2011-strain"'}
FREE_SLIP = {"artificial_viscosity_walls": '"free-slip"'}
WALL_FRICTION = {"wall_friction": '"spalding1961"'}
# The flume's side walls of Lobovsky et al.'s tank, 150 mm apart (1610 x 150 x 600 mm).
SIDE_WALLS_LOBOVSKY = {"side_wall_friction": '"spalding1961"', "flume_width": "0.15"}
