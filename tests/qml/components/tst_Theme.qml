import QtQuick
import QtTest
import Neptus.Components

TestCase {
    name: "Theme"
    when: windowShown
    visible: true

    function cleanup() { Theme.palette = Theme.Day }

    // WCAG relative luminance: linear light, not the sRGB code values.
    function luminance(c) {
        const linear = v => v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4)
        return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b)
    }

    function test_touchTargetIsNineMillimetresOnThisScreen() {
        // The test's X server runs at 96 dpi: 3.78 px/mm.
        const pxPerMm = Screen.pixelDensity / Math.max(Screen.devicePixelRatio, 1)
        verify(pxPerMm > 2, "screen reports its size")
        compare(Theme.pixelsPerMm, pxPerMm)
        verify(Theme.touchTarget / pxPerMm >= 8.9, "touch target " + Theme.touchTarget / pxPerMm + " mm")
        compare(Theme.mm(10), Math.round(10 * pxPerMm))
    }

    // A screen's real density from its size: what 96 dpi calls 9 mm (34 px) is 5.8 mm
    // on a 10.1-inch 1280x800 tablet, and the touch target follows the real density.
    function test_theRealDensityOfAScreenOfKnownSize() {
        const tablet = Theme.densityOf(10.1, 1280, 800)
        fuzzyCompare(tablet * 25.4, 149.4, 0.1, "ppi of a 10.1-inch 1280x800 screen")
        fuzzyCompare(34 / tablet, 5.8, 0.05, "a 34-pixel button there, in mm")
        Theme.knownPixelsPerMm = tablet
        compare(Theme.pixelsPerMm, tablet)
        compare(Theme.touchTarget, Math.ceil(9 * tablet))
        verify(Theme.touchTarget >= 53, Theme.touchTarget + " px")
        Theme.knownPixelsPerMm = 0
        compare(Theme.pixelsPerMm, Screen.pixelDensity / Math.max(Screen.devicePixelRatio, 1), "as the screen says again")
    }

    function test_paletteSwitchesEveryColour() {
        Theme.palette = Theme.Day
        const day = { bg: String(Theme.background), text: String(Theme.text), normal: String(Theme.levelColor(1)) }
        Theme.palette = Theme.Night
        verify(String(Theme.background) !== day.bg)
        verify(String(Theme.text) !== day.text)
        verify(String(Theme.levelColor(1)) !== day.normal)
        compare(Theme.paletteNames[Theme.palette], "Night")
    }

    function test_dayIsHighContrast() {
        Theme.palette = Theme.Day
        // WCAG contrast ratio; 7:1 is the AAA level.
        const ratio = (luminance(Theme.background) + 0.05) / (luminance(Theme.text) + 0.05)
        verify(ratio >= 7, "contrast " + ratio)
    }

    function test_nightIsDarkAndRed() {
        Theme.palette = Theme.Night
        verify(luminance(Theme.background) < 0.02, "background luminance")
        verify(luminance(Theme.text) < 0.1, "text luminance " + luminance(Theme.text))
        for (const c of [Theme.text, Theme.textDim, Theme.accent]) {
            verify(c.r > 0 && c.g === 0 && c.b === 0, "red only: " + c)
        }
    }

    // A colour a file chose (a Neptus shape's blue) is itself by day, and red only at night.
    function test_aFilesColourIsRedOnlyAtNight() {
        Theme.palette = Theme.Day
        compare(Theme.userColor("#0000ff"), Qt.color("#0000ff"))
        Theme.palette = Theme.Night
        for (const c of ["#0000ff", "#00ff00", "#ffffff", "#660066"]) {
            const night = Theme.userColor(c)
            verify(night.r > 0 && night.g === 0 && night.b === 0, c + " at night: " + night)
        }
        verify(Theme.userColor("#ffffff").r > Theme.userColor("#000080").r, "as bright as it was")
        Theme.palette = Theme.Day
    }

    function test_nextPaletteCycles() {
        Theme.palette = Theme.Day
        Theme.nextPalette(); compare(Theme.palette, Theme.Dusk)
        Theme.nextPalette(); compare(Theme.palette, Theme.Night)
        Theme.nextPalette(); compare(Theme.palette, Theme.Day)
    }

    function test_levelColoursAreDistinctAndClamped() {
        for (let p = 0; p < 3; ++p) {
            Theme.palette = p
            const seen = {}
            for (let level = 0; level < Theme.levelNames.length; ++level)
                seen[String(Theme.levelColor(level))] = true
            compare(Object.keys(seen).length, Theme.levelNames.length, Theme.paletteNames[p])
        }
        compare(Theme.levelColor(99), Theme.levelColor(5))
        compare(Theme.levelColor(-1), Theme.levelColor(0))
    }

    // The operator's scale: text and controls grow with it; a touch target
    // never goes under 9 mm.
    function test_uiScaleNeverShrinksATouchTargetUnderNineMillimetres() {
        const ten = Theme.mm(10), target = Theme.touchTarget
        Theme.uiScale = 1.5
        compare(Theme.mm(10), Math.round(10 * Theme.pixelsPerMm * 1.5))
        verify(Theme.touchTarget > target * 1.4, "bigger with it")
        verify(Theme.fontPixelSize > 0)
        Theme.uiScale = 0.75
        verify(Theme.mm(10) < ten, "text and spacing smaller")
        compare(Theme.touchTarget, target, "a touch target stays 9 mm")
        Theme.uiScale = 1
    }
}
