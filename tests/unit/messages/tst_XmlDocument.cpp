#include "xml/XmlDocument.h"

#include <QElapsedTimer>

#include <gtest/gtest.h>

using neptus::xml::XmlDocument;

TEST(XmlDocument, ParsesAndWalksElements)
{
    const auto doc = XmlDocument::parse("<a x=\"1\"><b/>text<c y=\"&amp;\"/><b/></a>", QStringLiteral("mem.xml"));
    ASSERT_TRUE(doc) << doc.error().toString().toStdString();
    EXPECT_EQ(neptus::xml::elementName(doc->root()), QStringLiteral("a"));
    EXPECT_EQ(neptus::xml::attribute(doc->root(), "x"), QStringLiteral("1"));
    EXPECT_EQ(neptus::xml::childElements(doc->root()).size(), 3);
    EXPECT_EQ(neptus::xml::childElements(doc->root(), "b").size(), 2);
    EXPECT_EQ(neptus::xml::attribute(neptus::xml::firstChildElement(doc->root(), "c"), "y"), QStringLiteral("&"));
}

TEST(XmlDocument, MalformedInputNamesFileLineAndColumn)
{
    const auto doc = XmlDocument::parse("<a>\n  <b>\n</a>\n", QStringLiteral("broken.xml"));
    ASSERT_FALSE(doc);
    EXPECT_EQ(doc.error().file, QStringLiteral("broken.xml"));
    EXPECT_EQ(doc.error().line, 3);
    EXPECT_GT(doc.error().column, 0);
    EXPECT_TRUE(doc.error().toString().startsWith(QStringLiteral("broken.xml:3:"))) << doc.error().toString().toStdString();
}

TEST(XmlDocument, RejectsBillionLaughsQuickly)
{
    const char *bomb = R"(<?xml version="1.0"?>
<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
 <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
 <!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
 <!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;">
 <!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;">
 <!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;">
 <!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">
]>
<lolz>&lol9;</lolz>
)";
    QElapsedTimer timer;
    timer.start();
    const auto doc = XmlDocument::parse(bomb, QStringLiteral("bomb.xml"));
    ASSERT_FALSE(doc);
    EXPECT_TRUE(doc.error().message.contains(QStringLiteral("DOCTYPE"))) << doc.error().toString().toStdString();
    EXPECT_EQ(doc.error().line, 2);
}

TEST(XmlDocument, RejectsExternalEntities)
{
    const char *xxe = R"(<?xml version="1.0"?>
<!DOCTYPE foo [ <!ENTITY xxe SYSTEM "file:///etc/passwd"> ]>
<messages>&xxe;</messages>
)";
    const auto doc = XmlDocument::parse(xxe, QStringLiteral("xxe.xml"));
    ASSERT_FALSE(doc);
    EXPECT_TRUE(doc.error().message.contains(QStringLiteral("DOCTYPE")));

    const char *external = R"(<?xml version="1.0"?>
<!DOCTYPE messages SYSTEM "http://127.0.0.1:9/evil.dtd">
<messages/>
)";
    const auto doc2 = XmlDocument::parse(external, QStringLiteral("dtd.xml"));
    ASSERT_FALSE(doc2);
    EXPECT_TRUE(doc2.error().message.contains(QStringLiteral("DOCTYPE")));
}

TEST(XmlDocument, UndeclaredEntityIsAnError)
{
    const auto doc = XmlDocument::parse("<a>&nope;</a>", QStringLiteral("entity.xml"));
    ASSERT_FALSE(doc);
    EXPECT_TRUE(doc.error().message.contains(QStringLiteral("nope"))) << doc.error().toString().toStdString();
}

TEST(XmlDocument, EmptyMissingAndOversizedInputs)
{
    auto doc = XmlDocument::parse("", QStringLiteral("empty.xml"));
    ASSERT_FALSE(doc);
    EXPECT_TRUE(doc.error().message.contains(QStringLiteral("empty")));

    doc = XmlDocument::load(QStringLiteral("/nonexistent/defs.xml"));
    ASSERT_FALSE(doc);
    EXPECT_TRUE(doc.error().toString().startsWith(QStringLiteral("/nonexistent/defs.xml: cannot open")));

    doc = XmlDocument::parse(QByteArray(XmlDocument::maxBytes + 1, ' '), QStringLiteral("huge.xml"));
    ASSERT_FALSE(doc);
    EXPECT_TRUE(doc.error().message.contains(QStringLiteral("limited")));
}
