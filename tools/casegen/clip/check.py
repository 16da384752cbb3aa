def run_all():
    return True
