// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Review.h"

#include <QString>

namespace rs::render {

// Writes the review as a PDF through a temporary file (the old file stays
// whole if writing fails). Returns an error message naming the file, empty on
// success. Needs a QGuiApplication (fonts).
QString writeReviewPdf(const QString& path, const Review& review);

} // namespace rs::render
