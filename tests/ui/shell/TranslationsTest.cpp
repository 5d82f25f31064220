// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
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
