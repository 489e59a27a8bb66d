"""The edges that draw: maps, trajectories, the paper's figures and animations.

matplotlib is imported only when a function draws.
"""

from rollingdisk.plotting.animation import (
    FPS_RANGE as FPS_RANGE,
)
from rollingdisk.plotting.animation import (
    FRAMES_RANGE as FRAMES_RANGE,
)
from rollingdisk.plotting.animation import (
    PIXEL_BUDGET as PIXEL_BUDGET,
)
from rollingdisk.plotting.animation import (
    DiskPose as DiskPose,
)
from rollingdisk.plotting.animation import (
    animate as animate,
)
from rollingdisk.plotting.animation import (
    animation_html as animation_html,
)
from rollingdisk.plotting.animation import (
    body_frame as body_frame,
)
from rollingdisk.plotting.animation import (
    check_animation as check_animation,
)
from rollingdisk.plotting.animation import (
    disk_pose as disk_pose,
)
from rollingdisk.plotting.animation import (
    draw_disk as draw_disk,
)
from rollingdisk.plotting.animation import (
    poses as poses,
)
from rollingdisk.plotting.animation import (
    writer_for as writer_for,
)
from rollingdisk.plotting.figures import (
    FIGURE_HS as FIGURE_HS,
)
from rollingdisk.plotting.figures import (
    FIGURES as FIGURES,
)
from rollingdisk.plotting.figures import (
    SCALE_MAX as SCALE_MAX,
)
from rollingdisk.plotting.figures import (
    figure4 as figure4,
)
from rollingdisk.plotting.figures import (
    figure5 as figure5,
)
from rollingdisk.plotting.figures import (
    figure6 as figure6,
)
from rollingdisk.plotting.figures import (
    figure7 as figure7,
)
from rollingdisk.plotting.figures import (
    figure8 as figure8,
)
from rollingdisk.plotting.figures import (
    paper_figures as paper_figures,
)
from rollingdisk.plotting.plots import (
    CLASS_COLORS as CLASS_COLORS,
)
from rollingdisk.plotting.plots import (
    DPI_RANGE as DPI_RANGE,
)
from rollingdisk.plotting.plots import (
    IMAGE_FORMATS as IMAGE_FORMATS,
)
from rollingdisk.plotting.plots import (
    MapPlot as MapPlot,
)
from rollingdisk.plotting.plots import (
    check_dpi as check_dpi,
)
from rollingdisk.plotting.plots import (
    image_format as image_format,
)
from rollingdisk.plotting.plots import (
    plot_all_omega30_stable as plot_all_omega30_stable,
)
from rollingdisk.plotting.plots import (
    plot_backbone as plot_backbone,
)
from rollingdisk.plotting.plots import (
    plot_basin_map as plot_basin_map,
)
from rollingdisk.plotting.plots import (
    plot_contact_forces as plot_contact_forces,
)
from rollingdisk.plotting.plots import (
    plot_energy_error as plot_energy_error,
)
from rollingdisk.plotting.plots import (
    plot_euler_disk as plot_euler_disk,
)
from rollingdisk.plotting.plots import (
    plot_exact as plot_exact,
)
from rollingdisk.plotting.plots import (
    plot_exact_theta as plot_exact_theta,
)
from rollingdisk.plotting.plots import (
    plot_existence_map as plot_existence_map,
)
from rollingdisk.plotting.plots import (
    plot_nonlinear_map as plot_nonlinear_map,
)
from rollingdisk.plotting.plots import (
    plot_paths as plot_paths,
)
from rollingdisk.plotting.plots import (
    plot_rosette as plot_rosette,
)
from rollingdisk.plotting.plots import (
    plot_stability_map as plot_stability_map,
)
from rollingdisk.plotting.plots import (
    plot_theta as plot_theta,
)
from rollingdisk.plotting.plots import (
    plot_trajectory as plot_trajectory,
)
from rollingdisk.plotting.plots import (
    plot_varpi2_curves as plot_varpi2_curves,
)
from rollingdisk.plotting.plots import (
    plot_varpi2_surface as plot_varpi2_surface,
)
from rollingdisk.plotting.plots import (
    save_figure as save_figure,
)
from rollingdisk.plotting.plots import (
    trajectory_series as trajectory_series,
)

__all__ = [
    "DPI_RANGE",
    "IMAGE_FORMATS",
    "check_dpi",
    "image_format",
    "save_figure",
    "CLASS_COLORS",
    "MapPlot",
    "plot_existence_map",
    "plot_stability_map",
    "plot_all_omega30_stable",
    "plot_varpi2_surface",
    "plot_varpi2_curves",
    "plot_paths",
    "plot_theta",
    "plot_energy_error",
    "plot_contact_forces",
    "plot_trajectory",
    "trajectory_series",
    "plot_euler_disk",
    "plot_nonlinear_map",
    "plot_basin_map",
    "plot_exact_theta",
    "plot_rosette",
    "plot_backbone",
    "plot_exact",
    "FIGURE_HS",
    "SCALE_MAX",
    "figure4",
    "figure5",
    "figure6",
    "figure7",
    "figure8",
    "paper_figures",
    "FIGURES",
    "DiskPose",
    "body_frame",
    "disk_pose",
    "poses",
    "draw_disk",
    "animate",
    "animation_html",
    "check_animation",
    "writer_for",
    "FRAMES_RANGE",
    "FPS_RANGE",
    "PIXEL_BUDGET",
]
