#include "stimuli/sets/booklet_pdf.hpp"

#include <filesystem>
#include <stdexcept>

#include "stimuli/sets/booklet_code.hpp"
#include <cairo-pdf.h>

#include "core/image.hpp"

namespace tlab::stimuli {

namespace {

constexpr double kPageWidth = 595.0, kPageHeight = 842.0, kMargin = 50.0;  // A4 in points

void text(cairo_t* cr, double x, double y, const std::string& s, double size, bool bold = false) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, s.c_str());
}

// Words wrapped to `width`; returns the y below the last line.
double wrapped(cairo_t* cr, double x, double y, const std::string& s, double size, double width) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  std::string line, word;
  const auto flush = [&] {
    if (line.empty()) return;
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, line.c_str());
    y += 1.35 * size;
    line.clear();
  };
  for (std::size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == ' ') {
      const std::string candidate = line.empty() ? word : line + " " + word;
      cairo_text_extents_t e;
      cairo_text_extents(cr, candidate.c_str(), &e);
      if (e.x_advance > width && !line.empty()) {
        flush();
        line = word;
      } else {
        line = candidate;
      }
      word.clear();
    } else {
      word += s[i];
    }
  }
  flush();
  return y;
}

void box(cairo_t* cr, double x, double y, double w, double h) {
  cairo_set_line_width(cr, 1.2);
  cairo_rectangle(cr, x, y, w, h);
  cairo_stroke(cr);
}

void drawImage(cairo_t* cr, const std::string& pngPath, double x, double y, double maxW, double maxH, double* drawnHeight) {
  cairo_surface_t* image = cairo_image_surface_create_from_png(pngPath.c_str());
  if (cairo_surface_status(image) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(image);
    throw std::runtime_error(pngPath + ": cannot read the stimulus image for the booklet");
  }
  const double w = cairo_image_surface_get_width(image), h = cairo_image_surface_get_height(image);
  const double scale = std::min(maxW / w, maxH / h);
  cairo_save(cr);
  cairo_translate(cr, x + 0.5 * (maxW - w * scale), y);
  cairo_scale(cr, scale, scale);
  cairo_set_source_surface(cr, image, 0, 0);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(image);
  *drawnHeight = h * scale;
}

// Answer boxes: one per label when the question marks several candidates, else one wide box.
void answerBoxes(cairo_t* cr, double y, const RenderedStimulus& s) {
  text(cr, kMargin, y, "Answer", 12, true);
  y += 10;
  const double w = kPageWidth - 2 * kMargin;
  const auto& marks = s.probes.marks;
  if (marks.size() >= 2 && marks.size() <= 8) {
    const double bw = w / double(marks.size());
    for (std::size_t i = 0; i < marks.size(); ++i) {
      box(cr, kMargin + double(i) * bw + 4, y, bw - 8, 34);
      text(cr, kMargin + double(i) * bw + 10, y + 14, marks[i].label, 11, true);
    }
    y += 44;
  }
  box(cr, kMargin, y, w, 40);
  const std::string field = !s.probes.printable ? "this question cannot be answered on paper (" + s.probes.answerFormat + ")"
                            : s.probes.answerFormat.empty() ? "answer:" : "answer (" + s.probes.answerFormat + "):";
  text(cr, kMargin + 6, y + 14, field, 9);
  box(cr, kMargin, y + 50, 120, 26);
  text(cr, kMargin + 6, y + 66, "confidence 1-5:", 9);
}

}  // namespace

void writeBookletPdf(const std::string& path, const StimulusSetSpec& spec, const std::vector<RenderedStimulus>& stimuli, const std::string& folder) {
  std::vector<std::uint8_t> bytes;
  const auto append = [](void* closure, const unsigned char* data, unsigned int length) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(closure);
    out->insert(out->end(), data, data + length);
    return CAIRO_STATUS_SUCCESS;
  };
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(append, &bytes, kPageWidth, kPageHeight);
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, "Stimulus booklet");  // the set's name may name conditions
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "tlab stimuli");
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
  cairo_t* cr = cairo_create(surface);
  for (std::size_t i = 0; i < stimuli.size(); ++i) {
    const RenderedStimulus& s = stimuli[i];
    cairo_set_source_rgb(cr, 0, 0, 0);
    // Nothing on a page names a condition: a page number and a neutral code the manifest maps back.
    text(cr, kMargin, kMargin, "Page " + std::to_string(i + 1) + " of " + std::to_string(stimuli.size()), 14, true);
    text(cr, kMargin, kMargin + 16, "code " + bookletCode(s.sha256), 8);
    double imageHeight = 0.0;
    drawImage(cr, (std::filesystem::path(folder) / s.image).string(), kMargin, kMargin + 26, kPageWidth - 2 * kMargin, 430, &imageHeight);
    double y = kMargin + 26 + imageHeight + 24;
    if (!spec.questionPrefix.empty()) y = wrapped(cr, kMargin, y, spec.questionPrefix, 10, kPageWidth - 2 * kMargin) + 4;
    text(cr, kMargin, y, "Question", 12, true);
    y = wrapped(cr, kMargin, y + 16, s.probeSet >= 0 ? s.probes.text : "Describe what you see.", 11, kPageWidth - 2 * kMargin) + 10;
    answerBoxes(cr, y, s);
    cairo_show_page(cr);
  }
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(path + ": cannot draw the booklet (" + cairo_status_to_string(status) + ")");
  core::writeFileAtomically(path, bytes);
}

}  // namespace tlab::stimuli
