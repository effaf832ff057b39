"""scripts/plot_compare.py draws every method of the method table (ddb.methods()) with a
style of its own: its own colour, line style and marker, and a place in the legend's groups."""
import ddb


def test_every_method_has_a_style_and_a_group_of_its_own(load_script):
    plot = load_script("plot_compare")
    names = [m["name"] for m in ddb.methods()]
    missing = [n for n in names if n not in plot.STYLE]
    assert not missing, f"no style in plot_compare.py for {missing}"
    ungrouped = [n for n in names if n not in plot.ORDER]
    assert not ungrouped, f"in no legend group of plot_compare.py: {ungrouped}"
    colours = [str(plot.STYLE[n]["color"]) for n in names]
    assert len(set(colours)) == len(colours), f"colours shared: {colours}"
    looks = [(str(plot.STYLE[n]["ls"]), plot.STYLE[n]["marker"]) for n in names]
    assert len(set(looks)) == len(looks), f"line style and marker shared: {looks}"
