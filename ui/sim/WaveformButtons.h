// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QString>

#include <functional>

class QLabel;
class QLineEdit;
class QToolButton;
class QWidget;

namespace rs::ui {

class WaveformView;

// The buttons every target's waveform panel has beside its input line.
struct WaveformButtons {
    QToolButton* remove;    // the chosen trace; enabled while one is chosen
    QToolButton* zoomIn;    // wired to the view
    QToolButton* zoomOut;   // wired to the view
    QToolButton* fit;       // wired to the view
    QToolButton* exportVcd; // the panel writes the file
};

WaveformButtons makeWaveformButtons(QWidget* owner, WaveformView* view);

// Lays a waveform panel out: the input line and the buttons on top, the
// message, the view. Return in the input adds what it names; `add` returns
// why not, which the message shows.
void layOutWaveformPanel(QWidget* panel, QLineEdit* input, const QList<QToolButton*>& buttons,
                         QLabel* message, WaveformView* view,
                         std::function<QString(const QString&)> add);

} // namespace rs::ui
