"""Debian's Chromium, headless, driven through Selenium, for the tests of the pages (and the
HTML report's benchmark). Its profile, caches and crash reports stay in the folder it is
given, never in ~; the background connections Chromium would make on its own are off."""
import contextlib
import os
import shutil
from pathlib import Path

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMEDRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"


def start_chromium(folder, window="1200,900", console_log=False, page_load_timeout=60):
    """A new Chromium whose files are in `folder`; `console_log`: the page's console is kept
    for driver.get_log("browser")."""
    folder = Path(folder)
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     f"--window-size={window}", f"--user-data-dir={folder / 'chromium'}",
                     "--no-first-run", "--disable-extensions", "--disable-crash-reporter",
                     "--disable-breakpad", "--disable-background-networking",
                     "--disable-component-update", "--disable-sync"):
        options.add_argument(argument)
    if console_log:
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    home = folder / "chromium-home"
    home.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, HOME=str(home), XDG_CONFIG_HOME=str(home / ".config"),
               XDG_CACHE_HOME=str(home / ".cache"))
    service = Service(executable_path=CHROMEDRIVER, log_path=os.devnull, env=env)
    driver = webdriver.Chrome(service=service, options=options)
    driver.set_page_load_timeout(page_load_timeout)
    return driver


@contextlib.contextmanager
def chromium(folder, **settings):
    """start_chromium(folder, **settings), quit when the block ends."""
    driver = start_chromium(folder, **settings)
    try:
        yield driver
    finally:
        driver.quit()
