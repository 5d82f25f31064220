// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/Translations.h"
#include "ladder/Layout.h"
#include "ladder/UnitLadder.h"
#include "lang/Parser.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QFile>
#include <QPushButton>
#include <QTranslator>
#include <QXmlStreamReader>

#include <gtest/gtest.h>

namespace {

// Every string of the window has a translation: none is left unfinished or empty.
void expectComplete(const QString& path) {
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    QXmlStreamReader xml(&file);
    int messages = 0;
    QString source;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (xml.name() == QLatin1String("message"))
            ++messages;
        else if (xml.name() == QLatin1String("source"))
            source = xml.readElementText();
        else if (xml.name() == QLatin1String("translation")) {
            const bool unfinished =
                xml.attributes().value(QLatin1String("type")) == QLatin1String("unfinished");
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            EXPECT_FALSE(unfinished) << path.toStdString() << ": " << source.toStdString();
            EXPECT_FALSE(text.trimmed().isEmpty())
                << path.toStdString() << ": " << source.toStdString();
        }
    }
    EXPECT_FALSE(xml.hasError()) << xml.errorString().toStdString();
    EXPECT_GT(messages, 300);
}

TEST(Translations, SwedishIsComplete) {
    expectComplete(QStringLiteral(RUNGSMITH_SOURCE_DIR "/translations/rungsmith_sv.ts"));
}

TEST(Translations, GermanIsComplete) {
    expectComplete(QStringLiteral(RUNGSMITH_SOURCE_DIR "/translations/rungsmith_de.ts"));
}

} // namespace

namespace {

// The window's translations as the GUI's main installs them, taken out again
// so that the other tests keep their English.
class InstalledTranslations {
public:
    explicit InstalledTranslations(const QLocale& locale) {
        const QList<QTranslator*> before = qApp->findChildren<QTranslator*>();
        rs::ui::installTranslations(*qApp, locale);
        for (QTranslator* translator : qApp->findChildren<QTranslator*>())
            if (!before.contains(translator))
                m_added.push_back(translator);
    }
    ~InstalledTranslations() {
        for (QTranslator* translator : m_added) {
            QCoreApplication::removeTranslator(translator);
            delete translator;
        }
    }

private:
    QList<QTranslator*> m_added;
};

QString buttonText(QDialogButtonBox::StandardButton which) {
    QDialogButtonBox box(which);
    return box.button(which)->text();
}

} // namespace

TEST(Translations, QtsOwnButtonsSpeakSwedishAndGerman) {
    {
        InstalledTranslations swedish{QLocale(QLocale::Swedish)};
        EXPECT_EQ(buttonText(QDialogButtonBox::Cancel), QStringLiteral("Avbryt"));
        EXPECT_EQ(buttonText(QDialogButtonBox::Discard), QStringLiteral("Förkasta"));
    }
    {
        InstalledTranslations german{QLocale(QLocale::German)};
        EXPECT_EQ(buttonText(QDialogButtonBox::Cancel), QStringLiteral("Abbrechen"));
        EXPECT_EQ(buttonText(QDialogButtonBox::Save), QStringLiteral("Speichern"));
    }
    EXPECT_EQ(buttonText(QDialogButtonBox::Cancel), QStringLiteral("Cancel"));
}

TEST(Translations, TheLadderWritesAJumpsStepInTheWindowsLanguage) {
    const rs::lang::ParseResult parsed =
        rs::lang::parse("! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\nJ(+1) = I0.4\n");
    ASSERT_TRUE(parsed.diagnostics.empty());
    const auto pages = rs::ladder::unitLadder(parsed.document.units.front());
    auto jumpLabel = [&pages] {
        rs::ladder::LayoutContext context;
        const rs::ladder::NetworkLayout layout =
            rs::ladder::layoutNetwork(pages.front().ladder.networks.front(), context);
        for (const auto& element : layout.elements)
            if (element.kind == rs::ladder::ElementKind::Jump)
                return element.address;
        return QString();
    };
    EXPECT_EQ(jumpLabel(), QStringLiteral("step +1"));
    InstalledTranslations swedish{QLocale(QLocale::Swedish)};
    EXPECT_EQ(jumpLabel(), QStringLiteral("steg +1"));
}
