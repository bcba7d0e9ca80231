// SPDX-License-Identifier: GPL-3.0-or-later
#include "nmmGeometryTools/blockPreview/blockPreview.H"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

namespace
{

struct rgb { double r, g, b; };

//- Hue per material, a lightness per block: golden-ratio steps keep
//  neighbouring indices apart
rgb shade(std::size_t materialIndex, std::size_t blockIndex)
{
    static const rgb hues[] = {
        {0.85, 0.65, 0.35}, {0.45, 0.62, 0.82}, {0.55, 0.75, 0.45},
        {0.80, 0.50, 0.55}, {0.65, 0.55, 0.80}};
    const rgb h = hues[materialIndex%std::size(hues)];
    const double f = 0.75 + 0.45*std::fmod(0.618034*blockIndex, 1.0);
    return {std::min(1.0, h.r*f), std::min(1.0, h.g*f), std::min(1.0, h.b*f)};
}

} // End anonymous namespace


void nmm::writeBlockPreview
(
    const std::filesystem::path& png,
    const blockList& blocks,
    int widthPixels
)
{
    Eigen::AlignedBox2d box;
    for (const auto& s : blocks.shapes())
    {
        for (const auto& p : s.outer) box.extend(p);
    }
    if (box.isEmpty() || box.sizes().minCoeff() <= 0)
    {
        throw std::runtime_error("no blocks to draw in " + png.string());
    }
    const double margin = 10;
    const double scale = (widthPixels - 2*margin)/box.sizes().x();
    const int height = int(std::ceil(box.sizes().y()*scale + 2*margin));

    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface
    (
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, widthPixels, height),
        cairo_surface_destroy
    );
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr
    (
        cairo_create(surface.get()), cairo_destroy
    );
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    cairo_set_fill_rule(cr.get(), CAIRO_FILL_RULE_EVEN_ODD);
    cairo_set_line_join(cr.get(), CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_width(cr.get(), std::clamp(0.002*widthPixels, 0.5, 2.0));

    const auto toPixel = [&](const Eigen::Vector2d& p)
    {
        return Eigen::Vector2d
        (
            margin + (p.x() - box.min().x())*scale,
            height - margin - (p.y() - box.min().y())*scale
        );
    };
    const auto tracePath = [&](const pointLoop& loop)
    {
        for (std::size_t i = 0; i < loop.size(); ++i)
        {
            const Eigen::Vector2d q = toPixel(loop[i]);
            if (i == 0) cairo_move_to(cr.get(), q.x(), q.y());
            else cairo_line_to(cr.get(), q.x(), q.y());
        }
        cairo_close_path(cr.get());
    };

    std::map<std::string, std::size_t> materialIndex;
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        const auto& s = blocks.shapes()[b];
        const std::size_t m =
            materialIndex.emplace(s.material, materialIndex.size()).first->second;
        tracePath(s.outer);
        for (const auto& h : s.holes) tracePath(h);
        const rgb c = shade(m, b);
        cairo_set_source_rgb(cr.get(), c.r, c.g, c.b);
        cairo_fill_preserve(cr.get());
        cairo_set_source_rgb(cr.get(), 0.2, 0.2, 0.2);
        cairo_stroke(cr.get());
    }

    if (png.has_parent_path())
    {
        std::filesystem::create_directories(png.parent_path());
    }
    if (cairo_surface_write_to_png(surface.get(), png.c_str()) != CAIRO_STATUS_SUCCESS)
    {
        throw std::runtime_error("cannot write " + png.string());
    }
}
