"""Headless Chromium for the page tests, driven by Debian's python3-selenium through Debian's chromium-driver
(README command (b) installs both: experiments/setup_debian.sh). Nothing is downloaded: selenium is pointed at
/usr/bin/chromedriver and /usr/bin/chromium, never at its own driver manager.

  missing()            why a browser cannot be started here ('' when it can)
  start(width, height) a headless Chromium (--no-sandbox: the tests run as root in CI), console log captured
  console(driver)      the console entries since the last call: [{'level', 'message', ...}]
  severe(entries)      those of level SEVERE (errors: a failed load, an uncaught exception)
  screenshot(driver, path, scroll_y=0)   the viewport as PNG after scrolling to scroll_y
  wait_images(driver)  every <img> with a src loaded (lazy ones forced eager); returns those that failed
"""
import os
import shutil
import time

CHROMIUM = ["/usr/bin/chromium", "/usr/bin/chromium-browser"]
DRIVER = "/usr/bin/chromedriver"


def _binary():
    return next((p for p in CHROMIUM if os.path.exists(p)), shutil.which("chromium"))


def missing():
    """'' when headless Chromium can be driven here, else what is missing (for a skip message)."""
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "python3-selenium is not installed (apt-get install python3-selenium)"
    if not _binary():
        return "chromium is not installed (apt-get install chromium)"
    if not os.path.exists(DRIVER):
        return f"{DRIVER} is missing (apt-get install chromium-driver)"
    return ""


def start(width=1366, height=900):
    """A headless Chromium with its window at width x height CSS pixels and the console log kept."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    opts = webdriver.ChromeOptions()
    opts.binary_location = _binary()
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--hide-scrollbars",
                "--force-device-scale-factor=1", f"--window-size={width},{height}", "--no-first-run",
                "--disable-extensions", "--disable-background-networking"):
        opts.add_argument(arg)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(DRIVER), options=opts)
    driver.set_window_size(width, height)
    driver.set_page_load_timeout(60)
    return driver


def console(driver):
    return driver.get_log("browser")


def severe(entries):
    return [e for e in entries if e.get("level") == "SEVERE"]


def screenshot(driver, path, scroll_y=0):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    driver.execute_script("window.scrollTo(0, arguments[0]);", scroll_y)
    time.sleep(0.4)
    driver.save_screenshot(path)
    return path


def wait_images(driver, timeout=30):
    """Forces every lazy image to load and waits; returns the src of those that did not decode."""
    driver.execute_script("document.querySelectorAll('img[loading=lazy]').forEach(function(i){i.loading='eager';});")
    end = time.time() + timeout
    while time.time() < end:
        pending = driver.execute_script(
            "return Array.from(document.images).filter(function(i){return i.getAttribute('src') && !i.complete;})"
            ".length;")
        if not pending:
            break
        time.sleep(0.2)
    return driver.execute_script(
        "return Array.from(document.images).filter(function(i){return i.getAttribute('src') && "
        "(!i.complete || i.naturalWidth === 0);}).map(function(i){return i.getAttribute('src').slice(0, 120);});")
