// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLabel>
#include <QPointer>

namespace rs::ui {

class ProjectDocument;
class SettledCompile;

// A page's line with a program signature (docs/review.md): the project's or
// one unit's, of the project as it is now, what `rungsmith-cli signature`
// prints, as the document's SettledCompile computes it while the line shows.
// While the project has errors there is none, and the line says so.
class SignatureLabel : public QLabel {
    Q_OBJECT
public:
    static constexpr int kProject = -1;

    explicit SignatureLabel(QWidget* parent = nullptr);

    // The project's signature (kProject) or the unit's with this station.
    void setSource(ProjectDocument* document, int station);
    // A signature is being computed, or waits for the project to settle.
    bool isComputing() const;

private:
    void showOutcome();

    QPointer<SettledCompile> m_compile;
    int m_station = kProject;
};

} // namespace rs::ui
