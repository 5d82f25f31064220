// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QLabel;
class QLineEdit;
class QToolButton;

namespace rs::ui {

class Pl110Document;
class Pl110Simulation;
class WaveformView;

// The simulated PL110's waveform: the variables recorded (every named one
// to begin with; more by address or name), drawn over virtual time by the
// waveform view every target shares, and exported as a VCD.
class Pl110WaveformPanel : public QWidget {
    Q_OBJECT
public:
    Pl110WaveformPanel(Pl110Document* document, Pl110Simulation* simulation,
                       QWidget* parent = nullptr);

    // Records an address or a declared name; an empty string, or why not.
    QString add(const QString& variable);
    // Writes the recording; an empty string, or why not. Without a path, asks for one.
    QString exportVcd(const QString& path = {});
    void recordingChanged();

private:
    Pl110Document* m_document;
    Pl110Simulation* m_simulation;
    WaveformView* m_view;
    QLineEdit* m_input;
    QLabel* m_message;
    QToolButton* m_remove;
};

} // namespace rs::ui
